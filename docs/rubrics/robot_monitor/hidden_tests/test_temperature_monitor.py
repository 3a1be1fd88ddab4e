"""The temperature_monitor node: it must run and publish a temperature reading."""

from sensor_msgs.msg import Temperature
from std_msgs.msg import Float32

ACCEPTED = {'sensor_msgs/msg/Temperature': Temperature, 'std_msgs/msg/Float32': Float32}


def _temperature_topic(listener):
    if 'temperature_monitor' not in listener.node.get_node_names():
        return None  # not discovered yet
    for topic, types in listener.node.get_publisher_names_and_types_by_node(
            'temperature_monitor', '/'):
        for name in types:
            if name in ACCEPTED:
                return topic, ACCEPTED[name]
    return None


def test_runs_and_publishes_a_temperature(start_node, listener, exit_message):
    node = start_node('temperature_monitor')
    found = listener.spin_until(
        lambda: _temperature_topic(listener) is not None or node.poll() is not None, 15.0)
    assert node.poll() is None, exit_message('temperature_monitor', node)
    assert found, ('the node `temperature_monitor` publishes no sensor_msgs/Temperature '
                   '(or std_msgs/Float32) topic')
    topic, msg_type = _temperature_topic(listener)
    received = listener.collect(msg_type, topic)
    assert listener.spin_until(lambda: received, 15.0), f'nothing arrived on `{topic}`'
