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

"""The navigation nodes driven through ROS: map and goal in, a collision-free path out."""

import math

from geometry_msgs.msg import PoseStamped, Twist
from nav_msgs.msg import OccupancyGrid, Odometry, Path
import numpy as np
from physical_ai_navigation.nodes.path_follower import PathFollowerNode
from physical_ai_navigation.nodes.path_planner import MAP_QOS, PathPlannerNode
from physical_ai_navigation.planning.grid_map import GridMap, inflate
import pytest
from sensor_msgs.msg import LaserScan


def occupancy_grid() -> OccupancyGrid:
    """Return a 4 m map (0.1 m cells, origin -2, -2), walled at x = 0 but for y in [1, 1.6)."""
    data = np.zeros((40, 40), dtype=np.int8)
    data[:, 20] = 100
    data[30:36, 20] = 0
    msg = OccupancyGrid()
    msg.header.frame_id = 'map'
    msg.info.resolution = 0.1
    msg.info.width, msg.info.height = 40, 40
    msg.info.origin.position.x = msg.info.origin.position.y = -2.0
    msg.info.origin.orientation.w = 1.0
    msg.data = data.flatten().tolist()
    return msg


def odometry(x: float, y: float, yaw: float = 0.0) -> Odometry:
    msg = Odometry()
    msg.pose.pose.position.x, msg.pose.pose.position.y = x, y
    msg.pose.pose.orientation.z, msg.pose.pose.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
    return msg


def goal(x: float, y: float) -> PoseStamped:
    msg = PoseStamped()
    msg.header.frame_id = 'map'
    msg.pose.position.x, msg.pose.position.y = x, y
    msg.pose.orientation.w = 1.0
    return msg


def plan(ros, planner: str, target: PoseStamped) -> Path:
    node = ros.start(PathPlannerNode, planner=planner, robot_radius=0.15)
    paths = ros.collect(Path, '/plan')
    ros.probe.create_publisher(OccupancyGrid, '/map', MAP_QOS).publish(occupancy_grid())
    odom = ros.publisher(Odometry, '/odom')
    goals = ros.publisher(PoseStamped, '/goal_pose')
    odom.publish(odometry(-1.52, -1.52))
    assert ros.spin_until(lambda: node.grid is not None and node.position == (-1.52, -1.52))
    assert ros.spin_until(lambda: paths, action=lambda: goals.publish(target))
    return paths[0]


@pytest.mark.parametrize('planner', ['astar', 'dijkstra', 'rrt'])
def test_map_and_goal_give_a_collision_free_path(ros, planner, assert_path_free):
    path = plan(ros, planner, goal(1.52, -1.52))
    points = [(p.pose.position.x, p.pose.position.y) for p in path.poses]
    assert path.header.frame_id == 'map' and len(points) >= 2
    assert points[0] == pytest.approx((-1.55, -1.55))  # the start cell's centre
    assert points[-1] == pytest.approx((1.55, -1.55))
    free = inflate(GridMap.from_msg(occupancy_grid()).free_mask(), 1.5)
    # Continuous cell coordinates (cell centres at integers): RRT waypoints are not centres.
    cells = [((y + 2.0) / 0.1 - 0.5, (x + 2.0) / 0.1 - 0.5) for x, y in points]
    assert_path_free(free, cells)
    assert any(abs(x) < 0.1 and 1.0 <= y < 1.6 for x, y in points)  # through the gap


def test_unreachable_goal_gives_an_empty_path(ros):
    path = plan(ros, 'astar', goal(0.0, -1.0))  # inside the wall
    assert path.poses == []


def test_follower_drives_along_the_path_and_stops_for_an_obstacle(ros):
    ros.start(PathFollowerNode, control_rate=50.0)
    commands = ros.collect(Twist, '/cmd_vel')
    path_pub = ros.publisher(Path, '/plan')
    odom_pub = ros.publisher(Odometry, '/odom')
    scan_pub = ros.publisher(LaserScan, '/scan')
    path = Path()
    path.poses = [goal(x, 0.5) for x in (0.0, 1.0, 2.0)]  # a line 0.5 m to the robot's left
    path_pub.publish(path)
    odom_pub.publish(odometry(0.0, 0.0))
    assert ros.spin_until(lambda: commands)
    assert commands[-1].linear.x > 0.0 and commands[-1].angular.z > 0.0

    scan = LaserScan(angle_min=-math.pi, angle_increment=math.pi / 4, range_min=0.05,
                     range_max=10.0)
    scan.angle_max = scan.angle_min + 7 * scan.angle_increment
    scan.ranges = [5.0, 5.0, 5.0, 5.0, 0.3, 5.0, 5.0, 5.0]  # 0.3 m straight ahead
    scan_pub.publish(scan)
    assert ros.spin_until(lambda: commands[-1].linear.x == 0.0)
    assert commands[-1].angular.z == 0.0


def test_follower_stops_at_the_goal(ros):
    node = ros.start(PathFollowerNode, control_rate=50.0)
    commands = ros.collect(Twist, '/cmd_vel')
    path = Path()
    path.poses = [goal(0.0, 0.0), goal(1.0, 0.0)]
    ros.publisher(Path, '/plan').publish(path)
    ros.publisher(Odometry, '/odom').publish(odometry(0.98, 0.0))
    assert ros.spin_until(lambda: commands)
    assert (commands[-1].linear.x, commands[-1].angular.z) == (0.0, 0.0)
    assert node.path == []
