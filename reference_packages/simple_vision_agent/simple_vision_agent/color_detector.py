# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""Detect green objects in camera images and publish what was found."""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from sensor_msgs.msg import Image, RegionOfInterest
from simple_vision_agent.detection import color_mask, find_blobs, segment
from simple_vision_agent.image_conversion import array_to_image, image_to_bgr8


class ColorDetector(Node):
    """
    Threshold ``/camera/image_raw`` in HSV and report the coloured objects.

    Publishes the segmented image (bgr8, boxes drawn) on ``/vision/segmented_image`` and the
    bounding box of the largest object on ``/vision/detection`` as a RegionOfInterest.
    """

    def __init__(self, **kwargs) -> None:
        super().__init__('color_detector', **kwargs)
        # OpenCV's HSV: hue 0-179, saturation and value 0-255; 40-80 is green.
        self.lower_hsv = list(self.declare_parameter('lower_hsv', [40, 40, 40]).value)
        self.upper_hsv = list(self.declare_parameter('upper_hsv', [80, 255, 255]).value)
        self.min_area = self.declare_parameter('min_area', 500.0).value
        self.subscription = self.create_subscription(
            Image, '/camera/image_raw', self.image_callback, 10)
        self.image_publisher = self.create_publisher(Image, '/vision/segmented_image', 10)
        self.detection_publisher = self.create_publisher(
            RegionOfInterest, '/vision/detection', 10)
        self.get_logger().info(
            f'Detecting color in HSV range: {self.lower_hsv} to {self.upper_hsv}')

    def image_callback(self, msg: Image) -> None:
        """Segment one image and publish the results; unsupported images are logged."""
        try:
            bgr = image_to_bgr8(msg)
        except ValueError as error:
            self.get_logger().error(f'Error converting image: {error}',
                                    throttle_duration_sec=5.0)
            return
        mask = color_mask(bgr, self.lower_hsv, self.upper_hsv)
        detections = find_blobs(mask, self.min_area)
        self.image_publisher.publish(
            array_to_image(segment(bgr, mask, detections), 'bgr8', header=msg.header))
        if detections:
            largest = detections[0]
            self.detection_publisher.publish(RegionOfInterest(
                x_offset=largest.x, y_offset=largest.y,
                width=largest.width, height=largest.height))
            self.get_logger().info(f'Detected {len(detections)} green objects.',
                                   throttle_duration_sec=1.0)


def main(args: list[str] | None = None) -> None:
    """Run the colour detector until interrupted."""
    rclpy.init(args=args)
    try:
        node = ColorDetector()
        try:
            rclpy.spin(node)
        finally:
            node.destroy_node()
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        rclpy.try_shutdown()


if __name__ == '__main__':
    main()
