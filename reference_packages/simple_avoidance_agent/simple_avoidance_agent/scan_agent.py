# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""The node both agents share: LaserScan on ``/scan`` in, Twist on ``/cmd_vel`` out."""

from typing import Callable

from geometry_msgs.msg import Twist
import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from sensor_msgs.msg import LaserScan
from simple_avoidance_agent.policy import Command


class ScanAgent(Node):
    """Publish one velocity command per non-empty scan; subclasses implement ``decide``."""

    def __init__(self, node_name: str, **kwargs) -> None:
        super().__init__(node_name, **kwargs)
        self.linear_speed = self.declare_parameter('linear_speed', 0.2).value
        self.angular_speed = self.declare_parameter('angular_speed', 0.5).value
        self.threshold_distance = self.declare_parameter('threshold_distance', 0.7).value
        self.publisher_ = self.create_publisher(Twist, '/cmd_vel', 10)
        self.subscription = self.create_subscription(LaserScan, '/scan', self.scan_callback, 10)
        self._last_reason = ''
        self.get_logger().info(f'{self.get_name()} has started, waiting for scan data...')

    def decide(self, scan: LaserScan) -> Command:
        """Return the command for ``scan``."""
        raise NotImplementedError

    def scan_callback(self, msg: LaserScan) -> None:
        """Publish the command for ``msg``; log only when the behaviour changes."""
        if not msg.ranges:
            return
        command = self.decide(msg)
        twist = Twist()
        twist.linear.x = command.linear
        twist.angular.z = command.angular
        self.publisher_.publish(twist)
        if command.reason != self._last_reason:
            log = self.get_logger().warn if command.turning else self.get_logger().info
            log(command.reason)
            self._last_reason = command.reason


def run(agent_factory: Callable[[], Node], args: list[str] | None = None) -> None:
    """Initialise rclpy, spin the agent until interrupted, then clean up."""
    rclpy.init(args=args)
    try:
        agent = agent_factory()
        try:
            rclpy.spin(agent)
        finally:
            agent.destroy_node()
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        rclpy.try_shutdown()
