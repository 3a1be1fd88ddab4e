# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""Lab 2.3: command humanoid joint positions and call a homing service, never blocking forever."""

from typing import Sequence

from joint_controller_agent.trajectory import single_point_trajectory
import rclpy
from rclpy.executors import ExternalShutdownException, SingleThreadedExecutor
from rclpy.node import Node
from rclpy.task import Future
from std_srvs.srv import Trigger
from trajectory_msgs.msg import JointTrajectory

DEFAULT_JOINTS = [
    'left_shoulder_joint', 'left_elbow_joint',
    'right_shoulder_joint', 'right_elbow_joint',
    'left_hip_joint', 'left_knee_joint', 'left_ankle_joint',
    'right_hip_joint', 'right_knee_joint', 'right_ankle_joint',
]


class HumanoidJointController(Node):
    """Publish JointTrajectory commands and call ``/robot_home_service`` with timeouts."""

    def __init__(self, **kwargs) -> None:
        super().__init__('humanoid_joint_controller', **kwargs)
        self.joint_names = list(self.declare_parameter('joint_names', DEFAULT_JOINTS).value)
        topic = self.declare_parameter(
            'trajectory_topic', '/joint_trajectory_controller/joint_trajectory').value
        service = self.declare_parameter('home_service', '/robot_home_service').value
        self.service_wait_timeout = self.declare_parameter('service_wait_timeout_sec', 1.0).value
        self.service_call_timeout = self.declare_parameter('service_call_timeout_sec', 5.0).value
        self.joint_publisher = self.create_publisher(JointTrajectory, topic, 10)
        self.home_client = self.create_client(Trigger, service)
        self.get_logger().info('Humanoid Joint Controller agent started.')

    def send_joint_command(self, positions: Sequence[float],
                           time_from_start_sec: float = 1.0) -> bool:
        """Publish a one-point trajectory to ``positions``; return False if it is invalid."""
        try:
            msg = single_point_trajectory(self.joint_names, positions, time_from_start_sec,
                                          stamp=self.get_clock().now().to_msg())
        except ValueError as error:
            self.get_logger().error(f'Joint command rejected: {error}')
            return False
        self.joint_publisher.publish(msg)
        self.get_logger().info(f'Sent joint command: {list(msg.points[0].positions)}')
        return True

    def call_home_service(self, timeout_sec: float | None = None) -> bool:
        """Call the homing service; False when it is missing, fails or does not answer in time."""
        if not self.home_client.wait_for_service(timeout_sec=self.service_wait_timeout):
            self.get_logger().warn('Home service not available.')
            return False
        future = self.home_client.call_async(Trigger.Request())
        timeout = self.service_call_timeout if timeout_sec is None else timeout_sec
        if not self._spin_until_done(future, timeout):
            # Forget the request so a late answer cannot fire on a future nobody waits for.
            self.home_client.remove_pending_request(future)
            future.cancel()
            self.get_logger().error(f'Home service did not answer within {timeout:.1f} s.')
            return False
        response = future.result()
        self.get_logger().info(f'Home service response: {response.success}, {response.message}')
        return response.success

    def pause(self, seconds: float) -> None:
        """Process callbacks for ``seconds`` (lets commands play out between poses)."""
        self._spin_until_done(Future(), seconds)

    def _spin_until_done(self, future: Future, timeout_sec: float) -> bool:
        executor = SingleThreadedExecutor(context=self.context)
        try:
            rclpy.spin_until_future_complete(self, future, executor=executor,
                                             timeout_sec=timeout_sec)
        finally:
            executor.shutdown()
        return future.done()


def wave_positions(joint_names: Sequence[str]) -> list[float]:
    """Return a pose with the right arm raised and the elbow bent, other joints at zero."""
    positions = [0.0] * len(joint_names)
    pose = {'right_shoulder_joint': -1.0, 'right_elbow_joint': -0.5}
    for index, name in enumerate(joint_names):
        positions[index] = pose.get(name, 0.0)
    return positions


def run_demo(controller: HumanoidJointController) -> bool:
    """Neutral pose, homing, then a wave; return whether homing succeeded."""
    controller.get_logger().info('Moving robot to a neutral pose.')
    controller.send_joint_command([0.0] * len(controller.joint_names), time_from_start_sec=2.0)
    controller.pause(2.5)
    controller.get_logger().info('Calling home service...')
    homed = controller.call_home_service()
    controller.get_logger().info('Moving right arm to a waving pose.')
    controller.send_joint_command(wave_positions(controller.joint_names), time_from_start_sec=1.5)
    controller.pause(2.0)
    return homed


def main(args: list[str] | None = None) -> None:
    """Run the demo motion once and exit."""
    rclpy.init(args=args)
    try:
        controller = HumanoidJointController()
        try:
            run_demo(controller)
        finally:
            controller.destroy_node()
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        rclpy.try_shutdown()


if __name__ == '__main__':
    main()
