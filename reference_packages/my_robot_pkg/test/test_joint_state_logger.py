# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""joint_state_logger: formatting and the node driven through ROS."""

from my_robot_pkg.joint_state_logger import describe_joints, format_value, JointStateLogger
from sensor_msgs.msg import JointState


def _state(**fields) -> JointState:
    return JointState(name=['hip', 'knee'], **fields)


def test_values_have_four_decimals():
    assert format_value([1.23456, 2.0], 1) == '2.0000'


def test_missing_values_are_not_applicable():
    assert format_value([], 0) == 'N/A'


def test_full_state_is_described():
    lines = describe_joints(_state(position=[0.1, 0.2], velocity=[1.0, 2.0], effort=[3.0, 4.0]))
    assert lines == [
        'Joint: hip, Position: 0.1000, Velocity: 1.0000, Effort: 3.0000',
        'Joint: knee, Position: 0.2000, Velocity: 2.0000, Effort: 4.0000',
    ]


def test_seed_mistake_empty_velocity_and_effort_do_not_crash():
    # The exercise formatted the 'N/A' placeholder with :.4f, a ValueError for any
    # JointState without velocities or efforts (common: position-only publishers).
    lines = describe_joints(_state(position=[0.1, 0.2]))
    assert lines[1] == 'Joint: knee, Position: 0.2000, Velocity: N/A, Effort: N/A'


def test_short_position_array_is_tolerated():
    assert describe_joints(_state(position=[0.5]))[1].startswith('Joint: knee, Position: N/A')


def test_node_logs_a_position_only_joint_state(ros):
    logger = ros.add(JointStateLogger(context=ros.context))
    publisher = ros.node('robot').create_publisher(JointState, '/joint_states', 10)
    state = _state(position=[0.1, -0.2])
    assert ros.spin_until(lambda: logger.last_report, tick=lambda: publisher.publish(state))
    assert logger.last_report == [
        'Joint: hip, Position: 0.1000, Velocity: N/A, Effort: N/A',
        'Joint: knee, Position: -0.2000, Velocity: N/A, Effort: N/A',
    ]
