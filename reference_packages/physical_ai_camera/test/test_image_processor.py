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

"""Unit tests of image conversion, edges, corners, stereo depth and colour detection."""

import cv2
import numpy as np
from physical_ai_camera.camera.image_processor import ImageProcessor
from physical_ai_camera.utils.color_detection import color_mask, detect_color_regions
from physical_ai_camera.utils.image_conversion import (
    array_to_image, image_to_array, image_to_bgr)
import pytest
from sensor_msgs.msg import Image

GREEN = (0, 200, 0)  # BGR


def square_image(color=GREEN, x=20, y=10, size=30, shape=(80, 100)) -> np.ndarray:
    image = np.zeros((*shape, 3), dtype=np.uint8)
    image[y:y + size, x:x + size] = color
    return image


@pytest.mark.parametrize('encoding,dtype,shape', [
    ('bgr8', np.uint8, (4, 5, 3)), ('mono8', np.uint8, (4, 5)), ('rgba8', np.uint8, (2, 3, 4)),
    ('16UC1', np.uint16, (3, 2)), ('32FC1', np.float32, (3, 4))])
def test_image_round_trip(encoding, dtype, shape):
    array = (np.random.default_rng(3).random(shape) * 1000).astype(dtype)
    msg = array_to_image(array, encoding)
    assert msg.step * msg.height == len(msg.data)
    np.testing.assert_array_equal(image_to_array(msg), array)


def test_padded_big_endian_image():
    msg = Image(height=2, width=1, encoding='16UC1', is_bigendian=1, step=4)
    msg.data = b'\x01\x02\x00\x00\x03\x04\x00\x00'
    np.testing.assert_array_equal(image_to_array(msg), [[0x0102], [0x0304]])


def test_image_to_bgr_swaps_rgb_and_expands_mono():
    rgb = np.zeros((2, 2, 3), np.uint8)
    rgb[:, :, 0] = 255  # red in RGB order
    assert image_to_bgr(array_to_image(rgb, 'rgb8'))[0, 0].tolist() == [0, 0, 255]
    assert image_to_bgr(array_to_image(np.full((2, 2), 7, np.uint8), 'mono8')).shape == (2, 2, 3)
    with pytest.raises(ValueError):
        image_to_bgr(array_to_image(np.zeros((2, 2), np.float32), '32FC1'))


def test_processor_converts_messages_both_ways():
    processor = ImageProcessor()
    image = square_image()
    msg = processor.opencv_to_ros_image(image)
    assert msg.encoding == 'bgr8'
    np.testing.assert_array_equal(processor.ros_image_to_opencv(msg), image)


def test_detect_edges_outlines_a_square():
    edges = ImageProcessor().detect_edges(square_image())
    assert edges.dtype == np.uint8 and edges.shape == (80, 100)
    assert edges[10:40, 15:25].any() and not edges[60:, 60:].any()


def test_detect_corners_returns_integer_pixels_with_numpy_2():
    corners = ImageProcessor().detect_corners(square_image(color=(255, 255, 255)))
    assert corners.dtype.kind == 'i' and corners.shape == (4, 2)
    expected = np.array([(20, 10), (20, 39), (49, 10), (49, 39)])
    assert np.abs(np.array(sorted(corners.tolist())) - expected).max() <= 1
    assert ImageProcessor().detect_corners(np.zeros((20, 20, 3), np.uint8)).shape == (0, 2)


def test_depth_from_a_shifted_stereo_pair():
    texture = (np.random.default_rng(7).random((120, 160)) * 255).astype(np.uint8)
    texture = cv2.resize(cv2.resize(texture, (40, 30)), (160, 120),
                         interpolation=cv2.INTER_NEAREST)
    shift = 8  # pixels: the right camera sees everything 8 pixels further left
    left = cv2.cvtColor(texture, cv2.COLOR_GRAY2BGR)
    right = np.roll(left, -shift, axis=1)
    processor = ImageProcessor(focal_length=500.0, baseline=0.2)
    depth = processor.calculate_depth_from_disparity(left, right)
    assert depth.dtype == np.float32 and depth.shape == (120, 160)
    valid = depth[depth > 0]
    assert valid.size > 0.3 * depth.size
    assert np.median(valid) == pytest.approx(500.0 * 0.2 / shift, rel=0.05)
    display = processor.depth_to_display(depth)
    assert display.dtype == np.uint8 and display.max() == 255


def test_detect_green_square():
    assert detect_color_regions(square_image(), [35, 80, 80], [85, 255, 255]) == [
        (20, 10, 30, 30)]


def test_detections_are_sorted_by_size_and_small_blobs_dropped():
    image = square_image(size=10)
    image[50:75, 60:95] = GREEN
    image[70:72, 5:7] = GREEN  # 4 pixels of noise
    boxes = detect_color_regions(image, [35, 80, 80], [85, 255, 255], min_area=50)
    assert boxes == [(60, 50, 35, 25), (20, 10, 10, 10)]
    assert detect_color_regions(image, [100, 80, 80], [130, 255, 255]) == []


def test_red_hue_range_wraps_around():
    image = square_image(color=(0, 0, 220))
    assert color_mask(image, [170, 80, 80], [10, 255, 255]).sum() == 30 * 30 * 255
