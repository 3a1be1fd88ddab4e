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

"""Data logger node: appends IMU and lidar readings to a CSV file for offline analysis."""

import csv
import math

from physical_ai_sensors.sensors.lidar_utils import clean_ranges, closest_reading
from physical_ai_sensors.utils.data_validation import imu_problems, scan_problems
from physical_ai_sensors.utils.node_runner import run_node
from physical_ai_sensors.utils.timestamp_sync import stamp_to_seconds
from rclpy.node import Node
from sensor_msgs.msg import Imu, LaserScan

COLUMNS = ('stamp', 'sensor', 'valid', 'x', 'y', 'z', 'wx', 'wy', 'wz')
"""CSV header. IMU rows: acceleration (x, y, z) and angular velocity (wx, wy, wz); scan rows:
nearest obstacle distance (x) and bearing (y)."""


class DataLoggerNode(Node):
    """Write one CSV row per received IMU or scan message to ``output_path``."""

    def __init__(self, **kwargs) -> None:
        """Open the output file (appending) and create the subscriptions."""
        super().__init__('data_logger_node', **kwargs)
        self.declare_parameter('output_path', 'sensor_log.csv')
        self.path = self.get_parameter('output_path').value
        self._file = open(self.path, 'a', newline='', encoding='utf-8')
        self._writer = csv.writer(self._file)
        if self._file.tell() == 0:
            self._writer.writerow(COLUMNS)
        self.rows = 0
        self.imu_sub = self.create_subscription(Imu, '/imu/raw', self.imu_callback, 10)
        self.scan_sub = self.create_subscription(LaserScan, '/scan', self.scan_callback, 10)
        self.get_logger().info(f'Logging sensor data to {self.path}')

    def _write(self, row) -> None:
        self._writer.writerow(row)
        self._file.flush()
        self.rows += 1

    def imu_callback(self, msg: Imu) -> None:
        """Log one IMU message."""
        acc, gyro = msg.linear_acceleration, msg.angular_velocity
        self._write((stamp_to_seconds(msg.header.stamp), 'imu', int(not imu_problems(msg)),
                     acc.x, acc.y, acc.z, gyro.x, gyro.y, gyro.z))

    def scan_callback(self, msg: LaserScan) -> None:
        """Log the nearest obstacle of one scan."""
        closest = closest_reading(clean_ranges(msg.ranges, msg.range_min, msg.range_max),
                                  msg.angle_min, msg.angle_increment)
        distance, bearing = closest if closest else (math.inf, math.nan)
        self._write((stamp_to_seconds(msg.header.stamp), 'scan', int(not scan_problems(msg)),
                     distance, bearing, '', '', '', ''))

    def destroy_node(self) -> None:
        """Close the log file, then destroy the node."""
        self._file.close()
        super().destroy_node()


def main(args=None) -> int:
    """Run the data logger node."""
    return run_node(DataLoggerNode, args)


if __name__ == '__main__':
    main()
