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
Path planner node: plans from the robot's position to each goal on the latest map.

Subscribes to ``/map`` (nav_msgs/OccupancyGrid, latched like map_server's), ``/odom`` and
``/goal_pose``; publishes nav_msgs/Path on ``/plan``. Without tf, the odometry frame is taken to
be the map frame.
"""

import math

from geometry_msgs.msg import PoseStamped
from nav_msgs.msg import OccupancyGrid, Odometry, Path
from physical_ai_navigation.planning.grid_map import GridMap
from physical_ai_navigation.planning.planners import plan_path, PLANNERS, PlanningError
from physical_ai_navigation.utils.geometry import pose_2d
from physical_ai_navigation.utils.node_runner import run_node
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy

MAP_QOS = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL,
                     reliability=ReliabilityPolicy.RELIABLE)
"""The QoS map_server publishes with: late subscribers still get the map."""


class PathPlannerNode(Node):
    """Plan a collision-free path with A*, Dijkstra or RRT whenever a goal arrives."""

    def __init__(self, **kwargs) -> None:
        """Declare parameters and create the subscriptions and the path publisher."""
        super().__init__('path_planner_node', **kwargs)
        self.declare_parameter('planner', 'astar')
        self.declare_parameter('robot_radius', 0.2)  # metres kept clear of obstacles
        self.declare_parameter('occupied_threshold', 50)
        self.declare_parameter('allow_unknown', False)
        self.declare_parameter('start_xy', [0.0, 0.0])  # used until odometry arrives
        self.planner = self.get_parameter('planner').value
        if self.planner not in PLANNERS:
            raise ValueError(f'planner must be one of {sorted(PLANNERS)}, not {self.planner!r}')
        start = self.get_parameter('start_xy').value
        self.position = (float(start[0]), float(start[1]))
        self.grid: GridMap | None = None
        self.map_frame = 'map'
        self.map_sub = self.create_subscription(OccupancyGrid, '/map', self.map_callback,
                                                MAP_QOS)
        self.odom_sub = self.create_subscription(Odometry, '/odom', self.odom_callback, 10)
        self.goal_sub = self.create_subscription(PoseStamped, '/goal_pose', self.goal_callback,
                                                 10)
        self.path_pub = self.create_publisher(Path, '/plan', 10)

    def map_callback(self, msg: OccupancyGrid) -> None:
        """Keep the latest map."""
        try:
            self.grid = GridMap.from_msg(msg)
        except ValueError as error:
            self.get_logger().error(f'Ignoring map: {error}')
            return
        self.map_frame = msg.header.frame_id or 'map'

    def odom_callback(self, msg: Odometry) -> None:
        """Track the robot's position."""
        self.position = (msg.pose.pose.position.x, msg.pose.pose.position.y)

    def goal_callback(self, msg: PoseStamped) -> None:
        """Plan to the goal; publish the path, or an empty path when planning fails."""
        path = Path()
        path.header.stamp = self.get_clock().now().to_msg()
        path.header.frame_id = self.map_frame
        if self.grid is None:
            self.get_logger().warn('No map received yet; cannot plan')
        else:
            goal = pose_2d(msg.pose)
            try:
                points = plan_path(
                    self.grid, self.position, goal[:2], planner=self.planner,
                    robot_radius=self.get_parameter('robot_radius').value,
                    occupied_threshold=self.get_parameter('occupied_threshold').value,
                    allow_unknown=self.get_parameter('allow_unknown').value)
            except PlanningError as error:
                self.get_logger().warn(f'Planning failed: {error}')
            else:
                path.poses = self._poses(path.header, points, goal[2])
                self.get_logger().info(f'Planned {len(points)} waypoints with {self.planner}')
        self.path_pub.publish(path)

    @staticmethod
    def _poses(header, points, goal_yaw: float) -> list:
        poses = []
        for index, (x, y) in enumerate(points):
            if index + 1 < len(points):
                yaw = math.atan2(points[index + 1][1] - y, points[index + 1][0] - x)
            else:
                yaw = goal_yaw
            pose = PoseStamped()
            pose.header = header
            pose.pose.position.x, pose.pose.position.y = float(x), float(y)
            pose.pose.orientation.z, pose.pose.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
            poses.append(pose)
        return poses


def main(args=None) -> int:
    """Run the path planner node."""
    return run_node(PathPlannerNode, args)


if __name__ == '__main__':
    main()
