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

"""The IMU processor node driven through ROS topics: IMU in, Euler angles and more out."""

import math

from builtin_interfaces.msg import Time
from geometry_msgs.msg import Vector3Stamped
from physical_ai_sensors.nodes.imu_processor import IMUProcessorNode
import pytest
from sensor_msgs.msg import Imu
from std_msgs.msg import Float32

GRAVITY = 9.80665


def imu(seconds: float, yaw: float = 0.0, ax: float = 0.0) -> Imu:
    msg = Imu()
    msg.header.stamp = Time(sec=int(seconds), nanosec=round((seconds % 1) * 1e9))
    msg.header.frame_id = 'imu_link'
    msg.orientation.z, msg.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
    msg.linear_acceleration.x, msg.linear_acceleration.z = ax, GRAVITY
    return msg


def test_node_parameters(ros):
    node = ros.start(IMUProcessorNode)
    assert node.get_parameter('publish_frequency').value == 100
    assert node.get_parameter('use_bias_correction').value is True


def test_imu_message_gives_euler_angles_and_acceleration_magnitude(ros):
    ros.start(IMUProcessorNode, publish_frequency=0)
    euler = ros.collect(Vector3Stamped, '/imu/euler_angles')
    magnitude = ros.collect(Float32, '/imu/acceleration_magnitude')
    publisher = ros.publisher(Imu, '/imu/raw')
    msg = imu(100.5, yaw=0.75, ax=3.0)
    assert ros.spin_until(lambda: euler and magnitude, action=lambda: publisher.publish(msg))
    assert (euler[0].vector.x, euler[0].vector.y, euler[0].vector.z) == pytest.approx(
        (0.0, 0.0, 0.75))
    assert euler[0].header.frame_id == 'imu_link'
    assert euler[0].header.stamp == msg.header.stamp
    assert magnitude[0].data == pytest.approx(math.hypot(3.0, GRAVITY), rel=1e-6)


def test_velocity_integrates_motion_acceleration_with_bias_correction(ros):
    ros.start(IMUProcessorNode, publish_frequency=0, accel_bias=[0.5, 0.0, 0.0])
    velocity = ros.collect(Vector3Stamped, '/imu/linear_velocity')
    publisher = ros.publisher(Imu, '/imu/raw')
    # 1.5 m/s^2 measured, 0.5 of it bias: 1 m/s^2 of motion for 1 s.
    ros.publish_all(publisher, [imu(10.0 + step * 0.1, yaw=math.pi / 2, ax=1.5)
                                for step in range(11)])
    assert ros.spin_until(lambda: len(velocity) == 10)
    # The IMU faces +y (yaw 90 degrees), so its forward motion is along the reference y axis.
    final = velocity[-1].vector
    assert (final.x, final.y, final.z) == pytest.approx((0.0, 1.0, 0.0), abs=1e-6)
    assert velocity[0].vector.y == pytest.approx(0.1)


def test_publish_frequency_limits_the_output_rate(ros):
    ros.start(IMUProcessorNode, publish_frequency=10)
    magnitude = ros.collect(Float32, '/imu/acceleration_magnitude')
    publisher = ros.publisher(Imu, '/imu/raw')
    ros.publish_all(publisher, [imu(5.0 + step * 0.01) for step in range(20)])  # 100 Hz
    ros.spin_until(lambda: len(magnitude) >= 3, timeout=2.0)
    assert len(magnitude) == 2


def test_invalid_message_is_skipped(ros):
    ros.start(IMUProcessorNode, publish_frequency=0)
    magnitude = ros.collect(Float32, '/imu/acceleration_magnitude')
    publisher = ros.publisher(Imu, '/imu/raw')
    bad = imu(1.0)
    bad.orientation.w = 2.0
    ros.spin_until(lambda: magnitude, timeout=0.5, action=lambda: publisher.publish(bad))
    assert magnitude == []
