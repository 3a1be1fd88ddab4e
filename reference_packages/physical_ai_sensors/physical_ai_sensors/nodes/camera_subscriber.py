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

"""Camera subscriber node: reports the brightness and sharpness of incoming images."""

from physical_ai_sensors.sensors.camera_utils import (
    image_to_array, mean_brightness, sharpness, to_grayscale)
from physical_ai_sensors.utils.data_validation import image_problems
from physical_ai_sensors.utils.node_runner import run_node
from rclpy.node import Node
from sensor_msgs.msg import Image
from std_msgs.msg import Float32


class CameraSubscriberNode(Node):
    """Publish the mean brightness (0-1) and the sharpness of every valid image."""

    def __init__(self, **kwargs) -> None:
        """Declare parameters and create the subscription and publishers."""
        super().__init__('camera_subscriber_node', **kwargs)
        self.declare_parameter('input_topic', '/camera/image_raw')
        self.declare_parameter('dark_threshold', 0.1)
        self.dark_threshold = self.get_parameter('dark_threshold').value
        self.subscription = self.create_subscription(
            Image, self.get_parameter('input_topic').value, self.image_callback, 10)
        self.brightness_pub = self.create_publisher(Float32, '/camera/brightness', 10)
        self.sharpness_pub = self.create_publisher(Float32, '/camera/sharpness', 10)
        self.frame_count = 0

    def image_callback(self, msg: Image) -> None:
        """Measure one image and publish its statistics."""
        problems = image_problems(msg)
        if problems:
            self.get_logger().warn(f'Skipping image: {"; ".join(problems)}')
            return
        array = image_to_array(msg)
        brightness = mean_brightness(array, msg.encoding)
        self.brightness_pub.publish(Float32(data=brightness))
        self.sharpness_pub.publish(Float32(data=sharpness(to_grayscale(array, msg.encoding))))
        self.frame_count += 1
        if brightness < self.dark_threshold:
            self.get_logger().warn(f'Image is dark (brightness {brightness:.2f})',
                                   throttle_duration_sec=5.0)


def main(args=None) -> int:
    """Run the camera subscriber node."""
    return run_node(CameraSubscriberNode, args)


if __name__ == '__main__':
    main()
