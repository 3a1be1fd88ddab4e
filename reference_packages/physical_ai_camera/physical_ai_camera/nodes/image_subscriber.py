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
Image subscriber node for Physical AI systems.

Subscribes to camera images, optionally detects edges, and republishes the result.
"""

import cv2
from physical_ai_camera.camera.image_processor import ImageProcessor
from physical_ai_camera.utils.node_runner import run_node
from rclpy.node import Node
from sensor_msgs.msg import Image


class ImageSubscriberNode(Node):
    """Process camera images and publish them on ``/camera/image_processed``."""

    def __init__(self, **kwargs) -> None:
        """Declare parameters, then create the subscription and publisher."""
        super().__init__('image_subscriber_node', **kwargs)
        self.image_processor = ImageProcessor()
        self.declare_parameter('input_topic', '/camera/image_raw')
        self.declare_parameter('enable_edge_detection', False)
        self.input_topic = self.get_parameter('input_topic').value
        self.enable_edge_detection = self.get_parameter('enable_edge_detection').value
        self.subscription = self.create_subscription(
            Image, self.input_topic, self.image_callback, 10)
        self.processed_publisher = self.create_publisher(Image, '/camera/image_processed', 10)
        self.frame_counter = 0
        self.get_logger().info(
            f'Image subscriber initialized - topic: {self.input_topic}, '
            f'edge detection: {self.enable_edge_detection}')

    def image_callback(self, msg: Image) -> None:
        """Process one image and publish the result."""
        try:
            cv_image = self.image_processor.ros_image_to_opencv(msg)
        except ValueError as error:
            self.get_logger().warn(f'Could not convert image message: {error}')
            return
        if self.enable_edge_detection:
            edges = self.image_processor.detect_edges(cv_image)
            processed_image = cv2.cvtColor(edges, cv2.COLOR_GRAY2BGR)
        else:
            processed_image = cv_image
        processed_msg = self.image_processor.opencv_to_ros_image(processed_image)
        processed_msg.header.stamp = msg.header.stamp  # keep the capture time
        processed_msg.header.frame_id = msg.header.frame_id
        self.processed_publisher.publish(processed_msg)
        self.frame_counter += 1
        if self.frame_counter % 30 == 0:
            height, width = cv_image.shape[:2]
            self.get_logger().info(f'Processed frame {self.frame_counter}: {width}x{height}')


def main(args=None) -> int:
    """Run the image subscriber node."""
    return run_node(ImageSubscriberNode, args)


if __name__ == '__main__':
    main()
