# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""NavCommander against a real NavigateToPose action server (nav2_msgs built from source)."""

import threading
import time

from action_msgs.msg import GoalStatus
from geometry_msgs.msg import PoseStamped
from nav2_msgs.action import NavigateToPose
from nav_agent.goals import Outcome
from nav_agent.nav_commander import main, NavCommander
import pytest
from rclpy.action import ActionServer, CancelResponse, GoalResponse
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.node import Node
from rclpy.parameter import Parameter


class FakeNavigator(Node):
    """A stand-in for Nav2's bt_navigator: succeeds, aborts, rejects or runs until canceled."""

    def __init__(self, behaviour: str, **kwargs) -> None:
        super().__init__('fake_bt_navigator', **kwargs)
        self.behaviour = behaviour
        self.goals: list[NavigateToPose.Goal] = []
        self.cancel_requested = threading.Event()
        self.stop = threading.Event()
        self._server = ActionServer(
            self, NavigateToPose, 'navigate_to_pose', execute_callback=self.execute,
            goal_callback=self.on_goal, cancel_callback=self.on_cancel,
            callback_group=ReentrantCallbackGroup())

    def on_goal(self, goal: NavigateToPose.Goal) -> GoalResponse:
        self.goals.append(goal)
        return GoalResponse.REJECT if self.behaviour == 'reject' else GoalResponse.ACCEPT

    def on_cancel(self, goal_handle) -> CancelResponse:
        self.cancel_requested.set()
        return CancelResponse.ACCEPT

    def execute(self, goal_handle) -> NavigateToPose.Result:
        feedback = NavigateToPose.Feedback(current_pose=PoseStamped(), distance_remaining=1.25)
        feedback.current_pose.pose.position.x = 0.5
        goal_handle.publish_feedback(feedback)
        if self.behaviour == 'abort':
            goal_handle.abort()
            return NavigateToPose.Result(error_code=9000, error_msg='no valid path')
        if self.behaviour == 'hang':
            while not goal_handle.is_cancel_requested and not self.stop.is_set():
                time.sleep(0.01)
            goal_handle.canceled()
            return NavigateToPose.Result()
        time.sleep(0.1)  # let the feedback reach the client before the result
        goal_handle.succeed()
        return NavigateToPose.Result(error_code=NavigateToPose.Result.NONE)


@pytest.fixture
def navigator(ros, request):
    server = ros.spin_in_background(FakeNavigator(request.param, context=ros.context))
    yield server
    server.stop.set()


@pytest.fixture
def commander(ros):
    overrides = [Parameter('server_timeout_sec', value=2.0),
                 Parameter('navigation_timeout_sec', value=5.0)]
    return ros.own(NavCommander(context=ros.context, parameter_overrides=overrides))


@pytest.mark.parametrize('navigator', ['succeed'], indirect=True)
def test_goal_reached(navigator, commander):
    result = commander.navigate(2.0, 1.5, 90.0)
    assert result.succeeded
    assert result.status == GoalStatus.STATUS_SUCCEEDED
    assert result.error_code == NavigateToPose.Result.NONE
    goal = navigator.goals[0]
    assert goal.pose.header.frame_id == 'map'
    assert (goal.pose.pose.position.x, goal.pose.pose.position.y) == (2.0, 1.5)
    assert goal.pose.pose.orientation.z == pytest.approx(0.7071067811865476)


@pytest.mark.parametrize('navigator', ['succeed'], indirect=True)
def test_seed_mistake_feedback_fields_are_read_from_feedback(navigator, commander):
    # The lesson read feedback_msg.current_pose; rclpy passes a FeedbackMessage whose
    # fields are under .feedback, so every feedback callback raised AttributeError.
    assert commander.navigate(1.0, 0.0, 0.0).succeeded
    assert commander.last_feedback is not None
    assert commander.last_feedback.distance_remaining == pytest.approx(1.25)
    assert commander.last_feedback.current_pose.pose.position.x == 0.5


@pytest.mark.parametrize('navigator', ['abort'], indirect=True)
def test_aborted_goal_is_reported_with_nav2_error(navigator, commander):
    result = commander.navigate(2.0, 1.5, 90.0)
    assert result.outcome is Outcome.ABORTED and not result.succeeded
    assert result.status == GoalStatus.STATUS_ABORTED
    assert (result.error_code, result.error_msg) == (9000, 'no valid path')


@pytest.mark.parametrize('navigator', ['reject'], indirect=True)
def test_rejected_goal(navigator, commander):
    assert commander.navigate(2.0, 1.5, 90.0).outcome is Outcome.REJECTED


@pytest.mark.parametrize('navigator', ['hang'], indirect=True)
def test_overlong_navigation_is_canceled(ros, navigator):
    overrides = [Parameter('navigation_timeout_sec', value=0.5)]
    commander = ros.own(NavCommander(context=ros.context, parameter_overrides=overrides))
    start = time.monotonic()
    assert commander.navigate(2.0, 1.5, 90.0).outcome is Outcome.TIMED_OUT
    assert navigator.cancel_requested.wait(timeout=2.0)
    assert time.monotonic() - start < 5.0


def test_missing_server_gives_up_after_the_timeout(ros):
    overrides = [Parameter('server_timeout_sec', value=0.5)]
    commander = ros.own(NavCommander(context=ros.context, parameter_overrides=overrides))
    start = time.monotonic()
    assert commander.navigate(2.0, 1.5, 90.0).outcome is Outcome.SERVER_UNAVAILABLE
    assert time.monotonic() - start < 2.0


def test_main_exits_non_zero_without_a_server():
    assert main(args=['--ros-args', '-p', 'server_timeout_sec:=0.3']) == 1
