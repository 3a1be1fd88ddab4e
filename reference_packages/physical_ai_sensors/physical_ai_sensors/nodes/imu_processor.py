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
IMU processor node for Physical AI systems.

Subscribes to raw IMU data and publishes orientation as Euler angles, the acceleration
magnitude and a velocity estimate for balance control and navigation.
"""

import math

from geometry_msgs.msg import Vector3Stamped
import numpy as np
from physical_ai_sensors.sensors.imu_processor import (
    IMUProcessor, rotation_matrix, validate_imu_message, VelocityIntegrator)
from physical_ai_sensors.utils.node_runner import run_node
from physical_ai_sensors.utils.timestamp_sync import stamp_to_nanoseconds
from rclpy.node import Node
from sensor_msgs.msg import Imu
from std_msgs.msg import Float32


class IMUProcessorNode(Node):
    """
    Process IMU data for Physical AI applications.

    Publishes at most ``publish_frequency`` times per second of message time (0 publishes every
    message); every message is still used for velocity integration. The velocity is expressed
    in the IMU's reference frame (``reference_frame``) and needs an orientation estimate.
    """

    def __init__(self, **kwargs) -> None:
        """Declare parameters, then create the subscription and publishers."""
        super().__init__('imu_processor_node', **kwargs)
        self.declare_parameter('publish_frequency', 100)  # Hz
        self.declare_parameter('use_bias_correction', True)
        self.declare_parameter('accel_bias', [0.0, 0.0, 0.0])
        self.declare_parameter('gyro_bias', [0.0, 0.0, 0.0])
        self.declare_parameter('gravity', 9.80665)
        self.declare_parameter('reference_frame', 'imu_reference')
        self.publish_freq = self.get_parameter('publish_frequency').value
        self.use_bias_correction = self.get_parameter('use_bias_correction').value
        self.reference_frame = self.get_parameter('reference_frame').value
        self.imu_processor = IMUProcessor(gravity=self.get_parameter('gravity').value)
        if self.use_bias_correction:
            self.imu_processor.set_bias(self.get_parameter('accel_bias').value,
                                        self.get_parameter('gyro_bias').value)
        self.integrator = VelocityIntegrator()
        self.last_published_ns: int | None = None
        self.subscription = self.create_subscription(Imu, '/imu/raw', self.imu_callback, 10)
        self.euler_angles_pub = self.create_publisher(Vector3Stamped, '/imu/euler_angles', 10)
        self.linear_velocity_pub = self.create_publisher(
            Vector3Stamped, '/imu/linear_velocity', 10)
        self.acceleration_mag_pub = self.create_publisher(
            Float32, '/imu/acceleration_magnitude', 10)
        self.get_logger().info(
            f'IMU processor started: {self.publish_freq} Hz, '
            f'bias correction: {self.use_bias_correction}')

    def _due(self, stamp_ns: int) -> bool:
        if self.publish_freq <= 0 or self.last_published_ns is None:
            return True
        period_ns = 1e9 / self.publish_freq
        return stamp_ns - self.last_published_ns >= 0.999 * period_ns

    def imu_callback(self, msg: Imu) -> None:
        """Validate, integrate and (when due) publish one IMU message."""
        if not validate_imu_message(msg):
            self.get_logger().warn('Received invalid IMU message, skipping')
            return
        has_orientation = msg.orientation_covariance[0] != -1.0
        stamp_ns = stamp_to_nanoseconds(msg.header.stamp)
        velocity = None
        if has_orientation:
            motion = self.imu_processor.extract_linear_acceleration(msg, remove_gravity=True)
            q = msg.orientation
            acceleration = rotation_matrix(q.x, q.y, q.z, q.w) @ np.array(motion)
            velocity = self.integrator.update(acceleration, stamp_ns * 1e-9)
        if not self._due(stamp_ns):
            return
        self.last_published_ns = stamp_ns
        if has_orientation:
            roll, pitch, yaw = self.imu_processor.extract_orientation_from_quaternion(msg)
            euler = self._vector(msg, msg.header.frame_id, (roll, pitch, yaw))
            self.euler_angles_pub.publish(euler)
        if velocity is not None:
            self.linear_velocity_pub.publish(self._vector(msg, self.reference_frame, velocity))
        acc = msg.linear_acceleration
        self.acceleration_mag_pub.publish(
            Float32(data=float(math.sqrt(acc.x ** 2 + acc.y ** 2 + acc.z ** 2))))

    @staticmethod
    def _vector(msg: Imu, frame_id: str, values) -> Vector3Stamped:
        out = Vector3Stamped()
        out.header.stamp = msg.header.stamp
        out.header.frame_id = frame_id
        out.vector.x, out.vector.y, out.vector.z = (float(v) for v in values)
        return out


def main(args=None) -> int:
    """Run the IMU processor node."""
    return run_node(IMUProcessorNode, args)


if __name__ == '__main__':
    main()
