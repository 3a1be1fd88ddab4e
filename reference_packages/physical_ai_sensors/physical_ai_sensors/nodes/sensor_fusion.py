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

"""Sensor fusion node: levels lidar scans with the IMU's tilt to locate the nearest obstacle."""

from geometry_msgs.msg import PointStamped
from physical_ai_sensors.sensors.fusion import closest_horizontal, level_points
from physical_ai_sensors.sensors.imu_processor import euler_from_quaternion
from physical_ai_sensors.sensors.lidar_utils import clean_ranges, scan_to_points
from physical_ai_sensors.utils.data_validation import scan_problems, validate_imu_message
from physical_ai_sensors.utils.node_runner import run_node
from physical_ai_sensors.utils.timestamp_sync import TimestampSynchronizer
from rclpy.node import Node
from sensor_msgs.msg import Imu, LaserScan


class SensorFusionNode(Node):
    """
    Pair IMU and scan messages by timestamp and publish the nearest obstacle, levelled.

    A humanoid's lidar tilts with its torso; rotating the scan by the IMU's roll and pitch gives
    obstacle positions in a gravity-aligned frame (``stabilized_frame``) with the robot's heading.
    """

    def __init__(self, **kwargs) -> None:
        """Declare parameters and create the synchroniser, subscriptions and publisher."""
        super().__init__('sensor_fusion_node', **kwargs)
        self.declare_parameter('sync_slop', 0.05)  # seconds
        self.declare_parameter('stabilized_frame', 'base_stabilized')
        self.frame = self.get_parameter('stabilized_frame').value
        self.sync = TimestampSynchronizer(2, self.get_parameter('sync_slop').value)
        self.imu_sub = self.create_subscription(Imu, '/imu/raw', self.imu_callback, 10)
        self.scan_sub = self.create_subscription(LaserScan, '/scan', self.scan_callback, 10)
        self.obstacle_pub = self.create_publisher(PointStamped, '/fusion/closest_obstacle', 10)

    def imu_callback(self, msg: Imu) -> None:
        """Queue an IMU message that carries an orientation."""
        if validate_imu_message(msg) and msg.orientation_covariance[0] != -1.0:
            self._fuse(self.sync.add(0, msg))

    def scan_callback(self, msg: LaserScan) -> None:
        """Queue a valid scan."""
        if not scan_problems(msg):
            self._fuse(self.sync.add(1, msg))

    def _fuse(self, group) -> None:
        if group is None:
            return
        imu, scan = group
        q = imu.orientation
        roll, pitch, _ = euler_from_quaternion(q.x, q.y, q.z, q.w)
        ranges = clean_ranges(scan.ranges, scan.range_min, scan.range_max)
        point = closest_horizontal(
            level_points(scan_to_points(ranges, scan.angle_min, scan.angle_increment),
                         roll, pitch))
        if point is None:
            return
        out = PointStamped()
        out.header.stamp = scan.header.stamp
        out.header.frame_id = self.frame
        out.point.x, out.point.y, out.point.z = (float(v) for v in point)
        self.obstacle_pub.publish(out)


def main(args=None) -> int:
    """Run the sensor fusion node."""
    return run_node(SensorFusionNode, args)


if __name__ == '__main__':
    main()
