"""The real ROS 2 Jazzy wheels work here: topics, services and actions, in-process."""

from __future__ import annotations

import os
import time

import pytest

pytestmark = pytest.mark.ros


def _spin_until(executor, done, timeout: float = 10.0) -> None:
    deadline = time.monotonic() + timeout
    while not done() and time.monotonic() < deadline:
        executor.spin_once(timeout_sec=0.05)
    assert done(), "timed out waiting for ROS"


def _executor(context, *nodes):
    from rclpy.executors import SingleThreadedExecutor

    executor = SingleThreadedExecutor(context=context)
    for node in nodes:
        executor.add_node(node)
    return executor


def test_harness_isolates_the_process(ros_context) -> None:
    assert os.environ["ROS_AUTOMATIC_DISCOVERY_RANGE"] == "OFF"
    assert os.environ["ROS_LOG_DIR"].endswith("ros_log")
    assert 1 <= int(os.environ["ROS_DOMAIN_ID"]) <= 101


def test_publisher_subscriber_round_trip(ros_context) -> None:
    from rclpy.node import Node
    from std_msgs.msg import String

    talker = Node("smoke_talker", context=ros_context)
    listener = Node("smoke_listener", context=ros_context)
    received: list[str] = []
    listener.create_subscription(String, "chatter", lambda m: received.append(m.data), 10)
    publisher = talker.create_publisher(String, "chatter", 10)
    executor = _executor(ros_context, talker, listener)

    def published_and_received() -> bool:
        publisher.publish(String(data="hello"))
        return bool(received)

    _spin_until(executor, published_and_received)
    assert received[0] == "hello"
    executor.shutdown()


def test_trigger_service_call(ros_context) -> None:
    from rclpy.node import Node
    from std_srvs.srv import Trigger

    server = Node("smoke_server", context=ros_context)
    client_node = Node("smoke_client", context=ros_context)

    def handle(_request, response):
        response.success = True
        response.message = "triggered"
        return response

    server.create_service(Trigger, "trigger", handle)
    client = client_node.create_client(Trigger, "trigger")
    executor = _executor(ros_context, server, client_node)
    _spin_until(executor, lambda: client.service_is_ready())
    future = client.call_async(Trigger.Request())
    _spin_until(executor, future.done)
    assert future.result().success is True
    assert future.result().message == "triggered"
    executor.shutdown()


def test_fibonacci_action_with_feedback_and_result(ros_context) -> None:
    from rclpy.action import ActionClient, ActionServer
    from rclpy.node import Node
    from test_msgs.action import Fibonacci

    server_node = Node("smoke_action_server", context=ros_context)
    client_node = Node("smoke_action_client", context=ros_context)

    def execute(goal_handle):
        sequence = [0, 1]
        for _ in range(goal_handle.request.order - 1):
            sequence.append(sequence[-1] + sequence[-2])
            goal_handle.publish_feedback(Fibonacci.Feedback(sequence=sequence))
        goal_handle.succeed()
        return Fibonacci.Result(sequence=sequence)

    ActionServer(server_node, Fibonacci, "fibonacci", execute)
    client = ActionClient(client_node, Fibonacci, "fibonacci")
    executor = _executor(ros_context, server_node, client_node)
    _spin_until(executor, client.server_is_ready)
    feedback: list[list[int]] = []
    send = client.send_goal_async(
        Fibonacci.Goal(order=5),
        feedback_callback=lambda f: feedback.append(list(f.feedback.sequence)))
    _spin_until(executor, send.done)
    goal_handle = send.result()
    assert goal_handle.accepted
    result = goal_handle.get_result_async()
    _spin_until(executor, result.done)
    assert list(result.result().result.sequence) == [0, 1, 1, 2, 3, 5]
    assert feedback, "no feedback arrived"
    assert all(f == [0, 1, 1, 2, 3, 5][: len(f)] for f in feedback)
    executor.shutdown()
