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

"""Lidar preprocessor node: cleans, filters and downsamples laser scans."""

import math

from physical_ai_sensors.sensors.lidar_utils import (
    clean_ranges, closest_reading, downsample, median_filter)
from physical_ai_sensors.utils.data_validation import scan_problems
from physical_ai_sensors.utils.node_runner import run_node
from rclpy.node import Node
from sensor_msgs.msg import LaserScan
from std_msgs.msg import Float32


class LidarPreprocessorNode(Node):
    """
    Publish a cleaned scan on ``/scan/filtered`` and the nearest obstacle distance.

    Invalid readings (NaN, outside the sensor's range) become +inf, a running median removes
    speckle, and downsampling keeps the nearest reading of each block of beams.
    """

    def __init__(self, **kwargs) -> None:
        """Declare parameters and create the subscription and publishers."""
        super().__init__('lidar_preprocessor_node', **kwargs)
        self.declare_parameter('median_window', 3)
        self.declare_parameter('downsample_factor', 1)
        self.median_window = self.get_parameter('median_window').value
        self.factor = self.get_parameter('downsample_factor').value
        if self.median_window < 1 or self.median_window % 2 == 0 or self.factor < 1:
            raise ValueError('median_window must be odd and positive, downsample_factor >= 1')
        self.subscription = self.create_subscription(LaserScan, '/scan', self.scan_callback, 10)
        self.filtered_pub = self.create_publisher(LaserScan, '/scan/filtered', 10)
        self.closest_pub = self.create_publisher(Float32, '/scan/closest_obstacle', 10)

    def scan_callback(self, msg: LaserScan) -> None:
        """Filter one scan and publish the results."""
        problems = scan_problems(msg)
        if problems:
            self.get_logger().warn(f'Skipping scan: {"; ".join(problems)}')
            return
        ranges = clean_ranges(msg.ranges, msg.range_min, msg.range_max)
        ranges = downsample(median_filter(ranges, self.median_window), self.factor)
        out = LaserScan()
        out.header = msg.header
        out.angle_min = msg.angle_min
        out.angle_increment = msg.angle_increment * self.factor
        out.angle_max = msg.angle_min + out.angle_increment * (len(ranges) - 1)
        out.time_increment = msg.time_increment * self.factor
        out.scan_time = msg.scan_time
        out.range_min, out.range_max = msg.range_min, msg.range_max
        out.ranges = [float(r) for r in ranges]
        self.filtered_pub.publish(out)
        closest = closest_reading(ranges, out.angle_min, out.angle_increment)
        self.closest_pub.publish(Float32(data=closest[0] if closest else math.inf))


def main(args=None) -> int:
    """Run the lidar preprocessor node."""
    return run_node(LidarPreprocessorNode, args)


if __name__ == '__main__':
    main()
