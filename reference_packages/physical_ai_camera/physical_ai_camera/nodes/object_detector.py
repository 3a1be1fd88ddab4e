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
Object detector node: finds objects of one colour and publishes their bounding box.

The chapter's extension challenge. Boxes are sensor_msgs/RegionOfInterest (common_interfaces
has no detection array without vision_msgs).
"""

from physical_ai_camera.utils.color_detection import detect_color_regions
from physical_ai_camera.utils.image_conversion import image_to_bgr
from physical_ai_camera.utils.node_runner import run_node
from rclpy.node import Node
from sensor_msgs.msg import Image, RegionOfInterest


class ObjectDetectorNode(Node):
    """
    Publish the bounding box of the largest object of the configured colour on every image.

    The colour is an HSV range (OpenCV scale: hue 0-179); the default is green. When no object
    is found, an empty box (all zeros) is published so listeners know the object is gone.
    """

    def __init__(self, **kwargs) -> None:
        """Declare parameters, then create the subscription and publisher."""
        super().__init__('object_detector_node', **kwargs)
        self.declare_parameter('input_topic', '/camera/image_raw')
        self.declare_parameter('lower_hsv', [35, 80, 80])
        self.declare_parameter('upper_hsv', [85, 255, 255])
        self.declare_parameter('min_area', 100)
        self.lower_hsv = list(self.get_parameter('lower_hsv').value)
        self.upper_hsv = list(self.get_parameter('upper_hsv').value)
        if len(self.lower_hsv) != 3 or len(self.upper_hsv) != 3:
            raise ValueError('lower_hsv and upper_hsv need three values: hue, saturation, value')
        self.min_area = self.get_parameter('min_area').value
        self.subscription = self.create_subscription(
            Image, self.get_parameter('input_topic').value, self.image_callback, 10)
        self.roi_publisher = self.create_publisher(RegionOfInterest, '/object_detector/roi', 10)

    def image_callback(self, msg: Image) -> None:
        """Detect the colour in one image and publish the largest box."""
        try:
            bgr = image_to_bgr(msg)
        except ValueError as error:
            self.get_logger().warn(f'Could not convert image message: {error}')
            return
        boxes = detect_color_regions(bgr, self.lower_hsv, self.upper_hsv, self.min_area)
        roi = RegionOfInterest()
        if boxes:
            roi.x_offset, roi.y_offset, roi.width, roi.height = boxes[0]
        self.roi_publisher.publish(roi)


def main(args=None) -> int:
    """Run the object detector node."""
    return run_node(ObjectDetectorNode, args)


if __name__ == '__main__':
    main()
