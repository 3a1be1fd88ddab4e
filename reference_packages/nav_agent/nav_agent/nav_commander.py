# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""Lab 2.2: send a NavigateToPose goal to Nav2 and report how it ended."""

from dataclasses import dataclass

from action_msgs.msg import GoalStatus
from nav2_msgs.action import NavigateToPose
from nav_agent.goals import Outcome, outcome_for_status, yaw_to_quaternion
import rclpy
from rclpy.action import ActionClient
from rclpy.action.client import ClientGoalHandle
from rclpy.executors import ExternalShutdownException, SingleThreadedExecutor
from rclpy.node import Node
from rclpy.task import Future


@dataclass(frozen=True)
class NavigationResult:
    """The end of one navigation request."""

    outcome: Outcome
    status: int = GoalStatus.STATUS_UNKNOWN
    error_code: int = 0
    error_msg: str = ''

    @property
    def succeeded(self) -> bool:
        """Return True when Nav2 reported the goal as reached."""
        return self.outcome is Outcome.SUCCEEDED


class NavCommander(Node):
    """A NavigateToPose client on ``navigate_to_pose`` whose every wait has a time limit."""

    def __init__(self, **kwargs) -> None:
        super().__init__('nav_commander', **kwargs)
        self.server_timeout = self.declare_parameter('server_timeout_sec', 10.0).value
        self.navigation_timeout = self.declare_parameter('navigation_timeout_sec', 300.0).value
        self.frame_id = self.declare_parameter('frame_id', 'map').value
        self.goal_x = self.declare_parameter('goal_x', 2.0).value
        self.goal_y = self.declare_parameter('goal_y', 1.5).value
        self.goal_yaw_deg = self.declare_parameter('goal_yaw_deg', 90.0).value
        self._action_client = ActionClient(self, NavigateToPose, 'navigate_to_pose')
        self.last_feedback: NavigateToPose.Feedback | None = None
        self.get_logger().info('Navigation Commander agent started.')

    def make_goal(self, x: float, y: float, yaw_degrees: float) -> NavigateToPose.Goal:
        """Return a goal at ``(x, y)`` in ``frame_id``, facing ``yaw_degrees``."""
        goal = NavigateToPose.Goal()
        goal.pose.header.frame_id = self.frame_id
        goal.pose.header.stamp = self.get_clock().now().to_msg()
        goal.pose.pose.position.x = float(x)
        goal.pose.pose.position.y = float(y)
        goal.pose.pose.orientation = yaw_to_quaternion(yaw_degrees)
        return goal

    def navigate(self, x: float, y: float, yaw_degrees: float) -> NavigationResult:
        """Send a goal and wait for its end; cancel it if it outlasts ``navigation_timeout``."""
        self.get_logger().info('Waiting for Nav2 action server...')
        if not self._action_client.wait_for_server(timeout_sec=self.server_timeout):
            self.get_logger().error(
                f'No navigate_to_pose action server after {self.server_timeout:.1f} s')
            return NavigationResult(Outcome.SERVER_UNAVAILABLE)
        self.get_logger().info(
            f'Sending navigation goal: x={x}, y={y}, yaw={yaw_degrees} degrees')
        goal_future = self._action_client.send_goal_async(
            self.make_goal(x, y, yaw_degrees), feedback_callback=self.feedback_callback)
        if not self._spin_until_done(goal_future, self.server_timeout):
            self.get_logger().error('Nav2 did not answer the goal request')
            return NavigationResult(Outcome.TIMED_OUT)
        goal_handle = goal_future.result()
        if not goal_handle.accepted:
            self.get_logger().error('Goal rejected by Nav2 server')
            return NavigationResult(Outcome.REJECTED)
        self.get_logger().info('Goal accepted by Nav2 server')
        result_future = goal_handle.get_result_async()
        if not self._spin_until_done(result_future, self.navigation_timeout):
            self.get_logger().warn(
                f'Navigation took longer than {self.navigation_timeout:.1f} s: canceling')
            self._cancel(goal_handle)
            return NavigationResult(Outcome.TIMED_OUT)
        return self._report(result_future.result())

    def feedback_callback(self, feedback_msg: NavigateToPose.Impl.FeedbackMessage) -> None:
        """Keep and log Nav2's progress (the fields live in ``feedback_msg.feedback``)."""
        self.last_feedback = feedback_msg.feedback
        position = self.last_feedback.current_pose.pose.position
        self.get_logger().info(
            f'Feedback: Current Pose (x={position.x:.2f}, y={position.y:.2f}), '
            f'Distance Remaining: {self.last_feedback.distance_remaining:.2f}m',
            throttle_duration_sec=1.0)

    def _report(self, response: NavigateToPose.Impl.GetResultService.Response
                ) -> NavigationResult:
        result = NavigationResult(outcome_for_status(response.status), response.status,
                                  response.result.error_code, response.result.error_msg)
        if result.succeeded:
            self.get_logger().info('Navigation Goal succeeded!')
        else:
            self.get_logger().warn(
                f'Navigation Goal {result.outcome.value} (status {result.status}, '
                f'error {result.error_code}: {result.error_msg!r})')
        return result

    def _cancel(self, goal_handle: ClientGoalHandle) -> None:
        cancel_future = goal_handle.cancel_goal_async()
        if (self._spin_until_done(cancel_future, self.server_timeout)
                and cancel_future.result().goals_canceling):
            self.get_logger().info('Goal cancel accepted')
        else:
            self.get_logger().warn('Nav2 did not accept the cancel request')

    def _spin_until_done(self, future: Future, timeout_sec: float) -> bool:
        executor = SingleThreadedExecutor(context=self.context)
        try:
            rclpy.spin_until_future_complete(self, future, executor=executor,
                                             timeout_sec=timeout_sec)
        finally:
            executor.shutdown()
        return future.done()


def main(args: list[str] | None = None) -> int:
    """Navigate to the goal given by the goal_* parameters; exit 0 only when it succeeded."""
    rclpy.init(args=args)
    succeeded = False
    try:
        commander = NavCommander()
        try:
            result = commander.navigate(commander.goal_x, commander.goal_y,
                                        commander.goal_yaw_deg)
            succeeded = result.succeeded
        finally:
            commander.destroy_node()
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        rclpy.try_shutdown()
    return 0 if succeeded else 1


if __name__ == '__main__':
    raise SystemExit(main())
