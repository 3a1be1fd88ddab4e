# Copyright 2026 Physical AI Robotics Team
#
# Licensed under the Apache License, Version 2.0 (the "License");
# you may not use this file except in compliance with the License.
# You may obtain a copy of the License at
#
#     http://www.apache.org/licenses/LICENSE-2.0
#
# Unless required by applicable law or agreed to in writing, software
# distributed under the License is distributed on an "AS IS" BASIS,
# WITHOUT WARRANTIES OR CONDITIONS OF ANY KIND, either express or implied.
# See the License for the specific language governing permissions and
# limitations under the License.

"""
Path follower node: drives along the planned path, stopping for obstacles ahead.

Subscribes to ``/plan`` (nav_msgs/Path), ``/odom`` and ``/scan``; publishes geometry_msgs/Twist
on ``/cmd_vel`` at ``control_rate``.
"""

from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry, Path
from physical_ai_navigation.control.pure_pursuit import nearest_obstacle_ahead, pure_pursuit
from physical_ai_navigation.utils.geometry import pose_2d
from physical_ai_navigation.utils.node_runner import run_node
from rclpy.node import Node
from sensor_msgs.msg import LaserScan


class PathFollowerNode(Node):
    """Follow the latest path with pure pursuit; stop at the goal or before an obstacle."""

    def __init__(self, **kwargs) -> None:
        """Declare parameters, create the subscriptions, publisher and control timer."""
        super().__init__('path_follower_node', **kwargs)
        for name, default in (('control_rate', 10.0), ('lookahead', 0.5), ('max_linear', 0.3),
                              ('max_angular', 1.0), ('goal_tolerance', 0.1),
                              ('stop_distance', 0.4), ('front_half_angle', 0.5)):
            self.declare_parameter(name, default)
        self.path: list[tuple[float, float]] = []
        self.pose: tuple[float, float, float] | None = None
        self.obstacle_distance = float('inf')
        self.path_sub = self.create_subscription(Path, '/plan', self.path_callback, 10)
        self.odom_sub = self.create_subscription(Odometry, '/odom', self.odom_callback, 10)
        self.scan_sub = self.create_subscription(LaserScan, '/scan', self.scan_callback, 10)
        self.cmd_pub = self.create_publisher(Twist, '/cmd_vel', 10)
        self.timer = self.create_timer(1.0 / self.get_parameter('control_rate').value,
                                       self.control_step)

    def _param(self, name: str) -> float:
        return self.get_parameter(name).value

    def path_callback(self, msg: Path) -> None:
        """Follow a new path (an empty one stops the robot)."""
        self.path = [(p.pose.position.x, p.pose.position.y) for p in msg.poses]

    def odom_callback(self, msg: Odometry) -> None:
        """Track the robot's pose."""
        self.pose = pose_2d(msg.pose.pose)

    def scan_callback(self, msg: LaserScan) -> None:
        """Keep the distance to the nearest obstacle in front."""
        self.obstacle_distance = nearest_obstacle_ahead(
            msg.ranges, msg.angle_min, msg.angle_increment, self._param('front_half_angle'))

    def control_step(self) -> None:
        """Publish one velocity command while there is a path to follow."""
        if not self.path or self.pose is None:
            return
        command = Twist()
        linear, angular, reached = pure_pursuit(
            self.pose, self.path, lookahead=self._param('lookahead'),
            max_linear=self._param('max_linear'), max_angular=self._param('max_angular'),
            goal_tolerance=self._param('goal_tolerance'))
        if reached:
            self.get_logger().info('Goal reached')
            self.path = []
        elif self.obstacle_distance < self._param('stop_distance') and linear > 0.0:
            self.get_logger().warn('Obstacle ahead: stopping', throttle_duration_sec=2.0)
        else:
            command.linear.x, command.angular.z = linear, angular
        self.cmd_pub.publish(command)


def main(args=None) -> int:
    """Run the path follower node."""
    return run_node(PathFollowerNode, args)


if __name__ == '__main__':
    main()
