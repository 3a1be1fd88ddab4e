# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""Temperature simulation, thresholds and the temperature_monitor node driven through ROS."""

import pytest
from rclpy.parameter import Parameter
from robot_monitor.health.temperature import classify, TemperatureLevel, TemperatureSimulation
from robot_monitor.temperature_monitor import TemperatureMonitor
from sensor_msgs.msg import Temperature


def test_temperature_starts_at_ambient_and_approaches_steady_state():
    motor = TemperatureSimulation(ambient_celsius=20.0, steady_state_celsius=60.0,
                                  time_constant_ticks=10.0)
    assert motor.temperature_at(0) == 20.0
    assert motor.temperature_at(10) == pytest.approx(20.0 + 40.0 * 0.6321, abs=1e-3)
    assert motor.temperature_at(1000) == pytest.approx(60.0)


def test_non_positive_time_constant_is_rejected():
    with pytest.raises(ValueError):
        TemperatureSimulation(time_constant_ticks=0.0).temperature_at(1)


@pytest.mark.parametrize(('celsius', 'level'), [
    (69.9, TemperatureLevel.OK),
    (70.0, TemperatureLevel.WARNING),
    (84.9, TemperatureLevel.WARNING),
    (85.0, TemperatureLevel.CRITICAL),
])
def test_classify_uses_inclusive_thresholds(celsius, level):
    assert classify(celsius, warning=70.0, critical=85.0) is level


def test_classify_rejects_inverted_thresholds():
    with pytest.raises(ValueError):
        classify(50.0, warning=90.0, critical=80.0)


def test_node_publishes_a_rising_stamped_temperature(ros):
    overrides = [
        Parameter('publish_period_sec', value=0.02),
        Parameter('time_constant_ticks', value=5.0),
        Parameter('frame_id', value='motor_link'),
    ]
    ros.add(TemperatureMonitor(context=ros.context, parameter_overrides=overrides))
    listener = ros.node('listener')
    received = []
    listener.create_subscription(Temperature, '/temperature', received.append, 10)

    assert ros.spin_until(lambda: len(received) >= 5, timeout_sec=5.0)
    values = [m.temperature for m in received]
    assert all(a < b for a, b in zip(values, values[1:]))
    assert {m.header.frame_id for m in received} == {'motor_link'}
    assert all(m.header.stamp.sec > 0 for m in received)
