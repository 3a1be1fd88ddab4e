# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""color_detector driven through ROS: Image in, segmented Image and RegionOfInterest out."""

import numpy as np
import pytest
from sensor_msgs.msg import Image, RegionOfInterest
from simple_vision_agent.color_detector import ColorDetector
from simple_vision_agent.image_conversion import array_to_image, image_to_array
from std_msgs.msg import Header


def _scene(encoding: str) -> Image:
    pixels = np.zeros((120, 160, 3), dtype=np.uint8)
    pixels[40:100, 50:110] = (0, 200, 0)  # a green square, identical in BGR and RGB
    pixels[5:25, 5:25] = (200, 0, 0) if encoding == 'bgr8' else (0, 0, 200)  # blue
    return array_to_image(pixels, encoding, header=Header(frame_id='camera_optical'))


def _run(ros, image: Image, until: str, timeout_sec: float = 5.0):
    ros.add(ColorDetector(context=ros.context))
    camera = ros.node('camera')
    publisher = camera.create_publisher(Image, '/camera/image_raw', 10)
    out = {'segmented': [], 'detection': []}
    camera.create_subscription(Image, '/vision/segmented_image', out['segmented'].append, 10)
    camera.create_subscription(RegionOfInterest, '/vision/detection', out['detection'].append,
                               10)
    ros.spin_until(lambda: out[until], timeout_sec=timeout_sec,
                   tick=lambda: publisher.publish(image))
    return out


@pytest.mark.parametrize('encoding', ['bgr8', 'rgb8'])
def test_green_square_is_detected(ros, encoding):
    out = _run(ros, _scene(encoding), until='detection')
    roi = out['detection'][0]
    assert (roi.x_offset, roi.y_offset, roi.width, roi.height) == (50, 40, 60, 60)


def test_segmented_image_keeps_the_header_and_only_the_object(ros):
    out = _run(ros, _scene('rgb8'), until='segmented')
    msg = out['segmented'][0]
    assert (msg.encoding, msg.header.frame_id) == ('bgr8', 'camera_optical')
    pixels = image_to_array(msg)
    assert pixels[70, 80].tolist() == [0, 200, 0]
    assert not pixels[5:25, 5:25].any()


def test_mono8_image_is_processed_without_detections(ros):
    grey = array_to_image(np.full((60, 80), 128, dtype=np.uint8), 'mono8')
    out = _run(ros, grey, until='segmented')
    assert out['segmented'][0].encoding == 'bgr8'
    assert not out['detection']


def test_unsupported_image_is_skipped_without_crashing(ros):
    depth = array_to_image(np.ones((10, 10), dtype=np.float32), '32FC1')
    out = _run(ros, depth, until='segmented', timeout_sec=1.0)
    assert out == {'segmented': [], 'detection': []}
