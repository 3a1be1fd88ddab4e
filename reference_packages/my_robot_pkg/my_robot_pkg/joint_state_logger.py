# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""Exercise 2.2: log the name, position, velocity and effort of every joint."""

from typing import Sequence

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from sensor_msgs.msg import JointState

MISSING = 'N/A'


def format_value(values: Sequence[float], index: int) -> str:
    """Return ``values[index]`` with 4 decimals, or 'N/A' when the array is too short."""
    # JointState may leave velocity/effort empty: format only real numbers with :.4f.
    return f'{values[index]:.4f}' if index < len(values) else MISSING


def describe_joints(msg: JointState) -> list[str]:
    """Return one log line per joint named in ``msg``."""
    return [
        f'Joint: {name}, Position: {format_value(msg.position, i)}, '
        f'Velocity: {format_value(msg.velocity, i)}, Effort: {format_value(msg.effort, i)}'
        for i, name in enumerate(msg.name)
    ]


class JointStateLogger(Node):
    """Log each ``/joint_states`` message, one line per joint."""

    def __init__(self, **kwargs) -> None:
        super().__init__('joint_state_logger', **kwargs)
        self.subscription = self.create_subscription(
            JointState, '/joint_states', self.joint_state_callback, 10)
        self.last_report: list[str] = []
        self.get_logger().info('Joint State Logger agent started, waiting for joint state data.')

    def joint_state_callback(self, msg: JointState) -> None:
        """Log the joints of ``msg`` and keep the lines as ``last_report``."""
        self.last_report = describe_joints(msg)
        self.get_logger().info('--- Joint State Update ---')
        for line in self.last_report:
            self.get_logger().info(line)


def main(args: list[str] | None = None) -> None:
    """Run the joint state logger until interrupted."""
    rclpy.init(args=args)
    try:
        node = JointStateLogger()
        try:
            rclpy.spin(node)
        finally:
            node.destroy_node()
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        rclpy.try_shutdown()


if __name__ == '__main__':
    main()
