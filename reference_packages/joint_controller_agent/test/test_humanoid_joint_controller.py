# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""The controller driven through ROS: trajectories out, Trigger homing calls with timeouts."""

import time

from joint_controller_agent.humanoid_joint_controller import HumanoidJointController, main
import pytest
import rclpy
from rclpy.parameter import Parameter
from std_srvs.srv import Trigger
from trajectory_msgs.msg import JointTrajectory

TOPIC = '/joint_trajectory_controller/joint_trajectory'


@pytest.fixture
def controller(ros):
    overrides = [Parameter('service_wait_timeout_sec', value=0.5),
                 Parameter('service_call_timeout_sec', value=0.5)]
    return ros.own(HumanoidJointController(context=ros.context, parameter_overrides=overrides))


def _home_server(ros, success: bool, message: str):
    node = ros.spin_in_background(rclpy.create_node('home_server', context=ros.context))

    def answer(request, response):
        response.success, response.message = success, message
        return response

    node.create_service(Trigger, '/robot_home_service', answer)
    return node


def test_joint_command_is_published_as_a_trajectory(ros, controller):
    listener = ros.node('listener')
    received = []
    listener.create_subscription(JointTrajectory, TOPIC, received.append, 10)
    positions = [0.1 * i for i in range(len(controller.joint_names))]

    assert ros.spin_until(lambda: received,
                          tick=lambda: controller.send_joint_command(positions, 2.25))
    msg = received[0]
    assert list(msg.joint_names) == controller.joint_names
    assert list(msg.points[0].positions) == pytest.approx(positions)
    assert (msg.points[0].time_from_start.sec, msg.points[0].time_from_start.nanosec) == (
        2, 250_000_000)
    assert msg.header.stamp.sec > 0


def test_wrong_number_of_positions_is_not_published(ros, controller):
    listener = ros.node('listener')
    received = []
    listener.create_subscription(JointTrajectory, TOPIC, received.append, 10)
    assert not controller.send_joint_command([0.0, 0.0])
    assert not ros.spin_until(lambda: received, timeout_sec=0.3)


@pytest.mark.parametrize(('success', 'message'), [(True, 'homed'), (False, 'motor fault')])
def test_home_service_answer_is_returned(ros, controller, success, message):
    _home_server(ros, success, message)
    assert controller.call_home_service() is success


def test_missing_home_service_returns_false_after_the_wait_timeout(controller):
    start = time.monotonic()
    assert controller.call_home_service() is False
    assert time.monotonic() - start < 2.0


def test_seed_mistake_silent_home_service_does_not_hang(ros, controller):
    # The lesson called spin_until_future_complete without a timeout: a server that never
    # answers blocked the agent forever. This server exists but is never spun.
    silent = ros.own(rclpy.create_node('silent_home_server', context=ros.context))
    silent.create_service(Trigger, '/robot_home_service', lambda request, response: response)
    start = time.monotonic()
    assert controller.call_home_service(timeout_sec=0.5) is False
    assert 0.4 < time.monotonic() - start < 2.5


def test_main_finishes_without_a_home_service():
    start = time.monotonic()
    main(args=['--ros-args', '-p', 'service_wait_timeout_sec:=0.2'])
    assert time.monotonic() - start < 10.0
