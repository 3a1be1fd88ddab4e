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

"""The camera nodes driven through ROS topics with real rclpy."""

import numpy as np
from physical_ai_camera.nodes.image_subscriber import ImageSubscriberNode
from physical_ai_camera.nodes.object_detector import ObjectDetectorNode
from physical_ai_camera.utils.image_conversion import array_to_image, image_to_array
from sensor_msgs.msg import Image, RegionOfInterest


def green_square_image() -> Image:
    image = np.zeros((120, 160, 3), dtype=np.uint8)
    image[40:70, 90:140] = (30, 210, 40)  # BGR green, 50 x 30 pixels at (90, 40)
    image[5:20, 5:20] = (200, 40, 40)  # a blue square that must be ignored
    msg = array_to_image(image, 'bgr8')
    msg.header.frame_id = 'camera_optical'
    return msg


def test_green_square_gives_its_bounding_box(ros):
    ros.start(ObjectDetectorNode)
    boxes = ros.collect(RegionOfInterest, '/object_detector/roi')
    publisher = ros.publisher(Image, '/camera/image_raw')
    msg = green_square_image()
    assert ros.spin_until(lambda: boxes, action=lambda: publisher.publish(msg))
    box = boxes[0]
    assert (box.x_offset, box.y_offset, box.width, box.height) == (90, 40, 50, 30)


def test_rgb_input_and_configured_colour(ros):
    ros.start(ObjectDetectorNode, lower_hsv=[100, 80, 80], upper_hsv=[130, 255, 255])
    boxes = ros.collect(RegionOfInterest, '/object_detector/roi')
    publisher = ros.publisher(Image, '/camera/image_raw')
    bgr = image_to_array(green_square_image())
    msg = array_to_image(bgr[:, :, ::-1], 'rgb8')  # same scene, RGB channel order
    assert ros.spin_until(lambda: boxes, action=lambda: publisher.publish(msg))
    box = boxes[0]
    assert (box.x_offset, box.y_offset, box.width, box.height) == (5, 5, 15, 15)


def test_no_object_gives_an_empty_box(ros):
    ros.start(ObjectDetectorNode)
    boxes = ros.collect(RegionOfInterest, '/object_detector/roi')
    publisher = ros.publisher(Image, '/camera/image_raw')
    msg = array_to_image(np.zeros((20, 20, 3), np.uint8), 'bgr8')
    assert ros.spin_until(lambda: boxes, action=lambda: publisher.publish(msg))
    assert (boxes[0].width, boxes[0].height) == (0, 0)


def test_image_subscriber_publishes_edges_as_colour_image(ros):
    ros.start(ImageSubscriberNode, enable_edge_detection=True)
    processed = ros.collect(Image, '/camera/image_processed')
    publisher = ros.publisher(Image, '/camera/image_raw')
    msg = green_square_image()
    msg.header.stamp.sec = 42
    assert ros.spin_until(lambda: processed, action=lambda: publisher.publish(msg))
    out = processed[0]
    assert (out.encoding, out.height, out.width) == ('bgr8', 120, 160)
    assert out.header.stamp.sec == 42 and out.header.frame_id == 'camera_optical'
    edges = image_to_array(out)
    assert set(np.unique(edges)) <= {0, 255} and edges[40:70, 85:95].any()


def test_image_subscriber_passes_images_through_and_skips_unsupported(ros):
    ros.start(ImageSubscriberNode)
    processed = ros.collect(Image, '/camera/image_processed')
    publisher = ros.publisher(Image, '/camera/image_raw')
    unsupported = Image(height=1, width=1, encoding='yuv422', step=2, data=b'ab')
    ros.spin_until(lambda: processed, timeout=0.3, action=lambda: publisher.publish(unsupported))
    assert processed == []
    msg = green_square_image()
    assert ros.spin_until(lambda: processed, action=lambda: publisher.publish(msg))
    np.testing.assert_array_equal(image_to_array(processed[0]), image_to_array(msg))
