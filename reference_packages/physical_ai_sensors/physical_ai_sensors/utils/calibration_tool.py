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

"""Calibration tool: estimates IMU biases from a robot standing still and level."""

import numpy as np
from physical_ai_sensors.sensors.imu_processor import estimate_bias
from physical_ai_sensors.utils.data_validation import validate_imu_message
from physical_ai_sensors.utils.node_runner import run_node
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile
from rclpy.task import Future
from sensor_msgs.msg import Imu
from std_msgs.msg import Float64MultiArray


def parameters_yaml(bias: np.ndarray, node_name: str = 'imu_processor_node') -> str:
    """Return a ROS 2 parameters file setting the imu_processor's biases."""
    values = [round(float(v), 6) + 0.0 for v in bias]  # + 0.0 turns -0.0 into 0.0
    accel = ', '.join(f'{v:.6f}' for v in values[:3])
    gyro = ', '.join(f'{v:.6f}' for v in values[3:])
    return (f'{node_name}:\n  ros__parameters:\n'
            f'    accel_bias: [{accel}]\n    gyro_bias: [{gyro}]\n')


class CalibrationToolNode(Node):
    """
    Collect ``sample_count`` IMU samples, then publish the bias once (latched).

    The result goes to ``/imu/calibration`` as [acc_x, acc_y, acc_z, gyro_x, gyro_y, gyro_z]
    and, when ``output_file`` is set, into a parameters file for the imu_processor.
    """

    def __init__(self, **kwargs) -> None:
        """Declare parameters and subscribe to the raw IMU."""
        super().__init__('calibration_tool_node', **kwargs)
        self.declare_parameter('sample_count', 200)
        self.declare_parameter('gravity', 9.80665)
        self.declare_parameter('output_file', '')
        self.sample_count = self.get_parameter('sample_count').value
        if self.sample_count < 1:
            raise ValueError('sample_count must be at least 1')
        self.samples: list[list[float]] = []
        self.finished = Future()
        latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
        self.result_pub = self.create_publisher(Float64MultiArray, '/imu/calibration', latched)
        self.subscription = self.create_subscription(Imu, '/imu/raw', self.imu_callback, 50)
        self.get_logger().info(f'Keep the robot still and level: {self.sample_count} samples')

    def imu_callback(self, msg: Imu) -> None:
        """Collect one sample; finish when enough were collected."""
        if self.finished.done() or not validate_imu_message(msg):
            return
        acc, gyro = msg.linear_acceleration, msg.angular_velocity
        self.samples.append([acc.x, acc.y, acc.z, gyro.x, gyro.y, gyro.z])
        if len(self.samples) >= self.sample_count:
            self._finish(estimate_bias(np.array(self.samples),
                                       self.get_parameter('gravity').value))

    def _finish(self, bias: np.ndarray) -> None:
        self.result_pub.publish(Float64MultiArray(data=[float(v) for v in bias]))
        output = self.get_parameter('output_file').value
        if output:
            with open(output, 'w', encoding='utf-8') as stream:
                stream.write(parameters_yaml(bias))
        self.get_logger().info(f'IMU bias: {np.round(bias, 5).tolist()}')
        self.finished.set_result(bias)


def main(args=None) -> int:
    """Run the calibration until enough samples were collected."""
    return run_node(CalibrationToolNode, args, until=lambda node: node.finished)


if __name__ == '__main__':
    main()
