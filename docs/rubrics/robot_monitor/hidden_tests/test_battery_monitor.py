"""The battery_monitor node, as the assignment specifies it (Lesson 3.1)."""

import pytest
from std_msgs.msg import Float32


def test_publishes_a_draining_voltage_on_battery_voltage(start_node, listener, exit_message):
    received = listener.collect(Float32, '/battery/voltage')
    node = start_node('battery_monitor')
    got_two = listener.spin_until(lambda: len(received) >= 2 or node.poll() is not None, 15.0)
    assert node.poll() is None, exit_message('battery_monitor', node)
    assert got_two and len(received) >= 2, 'expected a std_msgs/Float32 on /battery/voltage'
    first, second = received[0].data, received[1].data
    assert first == pytest.approx(12.6, abs=0.1), 'the simulated battery starts near 12.6 V'
    assert second < first, 'the voltage drains between messages'
    assert first - second == pytest.approx(0.01, abs=0.005), 'it drains by 0.01 V per message'


def test_runs_as_a_node_named_battery_monitor(start_node, listener, exit_message):
    node = start_node('battery_monitor')
    found = listener.spin_until(
        lambda: 'battery_monitor' in listener.node.get_node_names() or node.poll() is not None,
        15.0)
    assert node.poll() is None, exit_message('battery_monitor', node)
    assert found, 'no node named `battery_monitor` appeared'
