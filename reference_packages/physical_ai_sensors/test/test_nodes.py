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

"""The other nodes driven through ROS topics with real rclpy."""

import csv
import math

from builtin_interfaces.msg import Time
from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus
from geometry_msgs.msg import PointStamped
import numpy as np
from physical_ai_sensors.nodes.camera_subscriber import CameraSubscriberNode
from physical_ai_sensors.nodes.data_logger_node import DataLoggerNode
from physical_ai_sensors.nodes.lidar_preprocessor import LidarPreprocessorNode
from physical_ai_sensors.nodes.sensor_fusion import SensorFusionNode
from physical_ai_sensors.sensors.camera_utils import array_to_image
from physical_ai_sensors.utils.calibration_tool import CalibrationToolNode
from physical_ai_sensors.utils.data_validator import DataValidatorNode
import pytest
from rclpy.qos import DurabilityPolicy, QoSProfile
from sensor_msgs.msg import Image, Imu, LaserScan
from std_msgs.msg import Float32, Float64MultiArray


def scan(seconds: float, ranges) -> LaserScan:
    msg = LaserScan()
    msg.header.stamp = Time(sec=int(seconds), nanosec=round((seconds % 1) * 1e9))
    msg.angle_min, msg.angle_increment = -math.pi / 2, math.pi / 4
    msg.angle_max = msg.angle_min + msg.angle_increment * (len(ranges) - 1)
    msg.range_min, msg.range_max = 0.1, 10.0
    msg.ranges = [float(r) for r in ranges]
    return msg


def level_imu(seconds: float, pitch: float = 0.0) -> Imu:
    msg = Imu()
    msg.header.stamp = Time(sec=int(seconds), nanosec=round((seconds % 1) * 1e9))
    msg.orientation.y, msg.orientation.w = math.sin(pitch / 2), math.cos(pitch / 2)
    msg.linear_acceleration.z = 9.80665
    return msg


def test_lidar_preprocessor_cleans_and_reports_the_closest_obstacle(ros):
    ros.start(LidarPreprocessorNode)
    filtered = ros.collect(LaserScan, '/scan/filtered')
    closest = ros.collect(Float32, '/scan/closest_obstacle')
    publisher = ros.publisher(LaserScan, '/scan')
    msg = scan(1.0, [2.0, 0.01, 2.0, math.nan, 3.0])
    assert ros.spin_until(lambda: filtered and closest, action=lambda: publisher.publish(msg))
    assert list(filtered[0].ranges) == [2.0, 2.0, math.inf, 3.0, 3.0]
    assert closest[0].data == pytest.approx(2.0)


def test_lidar_preprocessor_downsamples(ros):
    ros.start(LidarPreprocessorNode, median_window=1, downsample_factor=2)
    filtered = ros.collect(LaserScan, '/scan/filtered')
    publisher = ros.publisher(LaserScan, '/scan')
    msg = scan(1.0, [4.0, 3.0, 2.0, 5.0, 1.0])
    assert ros.spin_until(lambda: filtered, action=lambda: publisher.publish(msg))
    assert list(filtered[0].ranges) == [3.0, 2.0, 1.0]
    assert filtered[0].angle_increment == pytest.approx(math.pi / 2)
    assert filtered[0].angle_max == pytest.approx(math.pi / 2)


def test_camera_subscriber_publishes_brightness(ros):
    ros.start(CameraSubscriberNode)
    brightness = ros.collect(Float32, '/camera/brightness')
    publisher = ros.publisher(Image, '/camera/image_raw')
    image = array_to_image(np.full((8, 8), 51, dtype=np.uint8), 'mono8')
    assert ros.spin_until(lambda: brightness, action=lambda: publisher.publish(image))
    assert brightness[0].data == pytest.approx(0.2)


def test_sensor_fusion_levels_the_scan_with_the_imu_pitch(ros):
    ros.start(SensorFusionNode)
    obstacles = ros.collect(PointStamped, '/fusion/closest_obstacle')
    imu_pub = ros.publisher(Imu, '/imu/raw')
    scan_pub = ros.publisher(LaserScan, '/scan')
    imu_pub.publish(level_imu(5.00, pitch=0.3))
    scan_pub.publish(scan(5.02, [9.0, 9.0, 2.0, 9.0, 9.0]))  # 2 m straight ahead
    assert ros.spin_until(lambda: obstacles)
    point = obstacles[0].point
    assert (point.x, point.y, point.z) == pytest.approx(
        (2 * math.cos(0.3), 0.0, -2 * math.sin(0.3)))
    assert obstacles[0].header.frame_id == 'base_stabilized'


def test_sensor_fusion_ignores_messages_too_far_apart(ros):
    ros.start(SensorFusionNode, sync_slop=0.01)
    obstacles = ros.collect(PointStamped, '/fusion/closest_obstacle')
    imu_pub = ros.publisher(Imu, '/imu/raw')
    scan_pub = ros.publisher(LaserScan, '/scan')
    imu_pub.publish(level_imu(5.0))
    scan_pub.publish(scan(5.5, [1.0] * 5))
    ros.spin_until(lambda: obstacles, timeout=0.5)
    assert obstacles == []


def test_data_validator_reports_stream_health(ros):
    ros.start(DataValidatorNode, report_period=0.05)
    reports = ros.collect(DiagnosticArray, '/diagnostics')
    publisher = ros.publisher(LaserScan, '/scan')
    bad = scan(1.0, [1.0, 1.0])  # two ranges for a five-beam angle range
    bad.angle_max = math.pi / 2
    publisher.publish(bad)

    def scan_reported():
        return reports and reports[-1].status[1].level == DiagnosticStatus.ERROR

    assert ros.spin_until(scan_reported)
    imu_status, scan_status, camera_status = reports[-1].status
    assert imu_status.level == DiagnosticStatus.STALE
    assert scan_status.message == 'number of ranges does not match the angle range'
    assert [(v.key, v.value) for v in scan_status.values] == [('valid', '0'), ('invalid', '1')]
    assert camera_status.name == 'physical_ai_sensors: camera'


def test_calibration_tool_estimates_and_saves_the_bias(ros, tmp_path):
    output = tmp_path / 'imu_bias.yaml'
    node = ros.start(CalibrationToolNode, sample_count=20, output_file=str(output))
    latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
    results = ros.collect(Float64MultiArray, '/imu/calibration', latched)
    publisher = ros.publisher(Imu, '/imu/raw')
    samples = [level_imu(1.0 + index * 0.01) for index in range(20)]
    for index, msg in enumerate(samples):
        msg.linear_acceleration.x = 0.2
        msg.angular_velocity.z = -0.01 if index % 2 else 0.03
    ros.publish_all(publisher, samples)
    assert ros.spin_until(lambda: results)
    assert list(results[0].data) == pytest.approx([0.2, 0.0, 0.0, 0.0, 0.0, 0.01])
    assert node.finished.done()
    assert 'accel_bias: [0.200000, 0.000000, 0.000000]' in output.read_text()


def test_data_logger_writes_csv_rows(ros, tmp_path):
    path = tmp_path / 'log.csv'
    node = ros.start(DataLoggerNode, output_path=str(path))
    imu_pub = ros.publisher(Imu, '/imu/raw')
    scan_pub = ros.publisher(LaserScan, '/scan')
    imu_pub.publish(level_imu(2.5))
    scan_pub.publish(scan(2.6, [3.0, 1.5, 3.0, 3.0, 3.0]))
    assert ros.spin_until(lambda: node.rows == 2)
    rows = list(csv.DictReader(path.read_text().splitlines()))
    by_sensor = {row['sensor']: row for row in rows}
    assert float(by_sensor['imu']['stamp']) == pytest.approx(2.5)
    assert float(by_sensor['imu']['z']) == pytest.approx(9.80665)
    assert float(by_sensor['scan']['x']) == pytest.approx(1.5)
    assert float(by_sensor['scan']['y']) == pytest.approx(-math.pi / 4)
