# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""Battery simulation and the battery_monitor node driven through ROS."""

import pytest
from rclpy.parameter import Parameter
from robot_monitor.battery_monitor import BatteryMonitor
from robot_monitor.health.battery import BatterySimulation, is_low
from std_msgs.msg import Float32


def test_voltage_drains_by_a_fixed_step():
    battery = BatterySimulation(initial_voltage=12.6, drain_per_tick=0.01)
    assert battery.voltage_at(0) == 12.6
    assert battery.voltage_at(1) == pytest.approx(12.59)
    assert battery.voltage_at(260) == 10.0


def test_voltage_never_goes_below_empty():
    assert BatterySimulation(initial_voltage=1.0, drain_per_tick=0.5).voltage_at(10) == 0.0


def test_negative_tick_is_rejected():
    with pytest.raises(ValueError):
        BatterySimulation().voltage_at(-1)


def test_low_means_strictly_below_threshold():
    assert not is_low(10.0, 10.0)
    assert is_low(9.99, 10.0)


def test_node_publishes_a_draining_voltage_that_goes_low(ros):
    overrides = [
        Parameter('publish_period_sec', value=0.02),
        Parameter('initial_voltage', value=10.05),
        Parameter('drain_per_tick', value=0.01),
    ]
    monitor = ros.add(BatteryMonitor(context=ros.context, parameter_overrides=overrides))
    listener = ros.node('listener')
    received = []
    listener.create_subscription(
        Float32, '/battery/voltage', lambda msg: received.append(msg.data), 10)

    assert ros.spin_until(lambda: len(received) >= 8, timeout_sec=5.0)
    assert all(a > b for a, b in zip(received, received[1:]))
    assert received[-1] < monitor.low_voltage
    assert received[-1] == pytest.approx(monitor.battery.voltage_at(monitor.tick - 1), abs=1e-5)
