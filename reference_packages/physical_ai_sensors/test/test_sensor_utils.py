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

"""Unit tests of the camera, lidar and fusion utilities."""

import math

import numpy as np
from physical_ai_sensors.sensors.camera_utils import (
    array_to_image, image_to_array, mean_brightness, sharpness, to_grayscale)
from physical_ai_sensors.sensors.fusion import closest_horizontal, level_points
from physical_ai_sensors.sensors.lidar_utils import (
    clean_ranges, closest_reading, downsample, median_filter, scan_to_points)
import pytest
from sensor_msgs.msg import Image


@pytest.mark.parametrize('encoding,dtype,shape', [
    ('bgr8', np.uint8, (4, 5, 3)), ('mono8', np.uint8, (4, 5)), ('rgba8', np.uint8, (2, 3, 4)),
    ('16UC1', np.uint16, (3, 2)), ('32FC1', np.float32, (3, 4))])
def test_image_round_trip(encoding, dtype, shape):
    rng = np.random.default_rng(1)
    array = (rng.random(shape) * 1000).astype(dtype)
    msg = array_to_image(array, encoding)
    assert (msg.height, msg.width, msg.encoding) == (shape[0], shape[1], encoding)
    assert msg.step * msg.height == len(msg.data)
    np.testing.assert_array_equal(image_to_array(msg), array)


def test_image_with_row_padding_and_big_endian_data():
    values = np.array([[1, 2], [300, 4000]], dtype='>u2')
    msg = Image(height=2, width=2, encoding='16UC1', is_bigendian=1, step=6)
    msg.data = b''.join(row.tobytes() + b'\xff\xff' for row in values)
    np.testing.assert_array_equal(image_to_array(msg), [[1, 2], [300, 4000]])


def test_image_conversion_rejects_bad_input():
    with pytest.raises(ValueError):
        image_to_array(Image(height=1, width=1, encoding='yuv422', step=2, data=b'ab'))
    with pytest.raises(ValueError):
        image_to_array(Image(height=2, width=2, encoding='mono8', step=2, data=b'ab'))
    with pytest.raises(ValueError):
        array_to_image(np.zeros((2, 2)), 'bgr8')


def test_brightness_weights_follow_the_channel_order():
    blue = np.zeros((2, 2, 3), dtype=np.uint8)
    blue[:, :, 0] = 255
    assert mean_brightness(blue, 'bgr8') == pytest.approx(0.114)
    assert mean_brightness(blue, 'rgb8') == pytest.approx(0.299)
    assert mean_brightness(np.full((2, 2), 255, np.uint8), 'mono8') == pytest.approx(1.0)


def test_sharpness_is_higher_for_edges_than_for_a_flat_image():
    flat = np.full((10, 10), 0.5)
    edges = np.zeros((10, 10))
    edges[:, ::2] = 1.0
    assert sharpness(flat) == 0.0
    assert sharpness(edges) > 1.0
    assert to_grayscale(np.full((2, 2), 65535, np.uint16), '16UC1') == pytest.approx(1.0)


def test_clean_ranges_marks_invalid_readings_as_infinite():
    cleaned = clean_ranges([0.05, 1.0, math.nan, 50.0, 2.0, -math.inf], 0.1, 30.0)
    assert cleaned.tolist() == [math.inf, 1.0, math.inf, math.inf, 2.0, math.inf]


def test_median_filter_removes_a_single_outlier():
    filtered = median_filter([1.0, 1.0, 9.0, 1.0, 1.0], 3)
    assert filtered.tolist() == [1.0, 1.0, 1.0, 1.0, 1.0]
    with pytest.raises(ValueError):
        median_filter([1.0], 2)


def test_downsample_keeps_the_nearest_reading_of_each_block():
    assert downsample([3.0, 1.0, 2.0, 5.0, 4.0], 2).tolist() == [1.0, 2.0, 4.0]
    assert downsample([3.0, 1.0], 1).tolist() == [3.0, 1.0]


def test_scan_to_points_and_closest_reading():
    ranges = [1.0, math.inf, 2.0]
    points = scan_to_points(ranges, -math.pi / 2, math.pi / 2)
    assert points == pytest.approx(np.array([[0.0, -1.0], [0.0, 2.0]]), abs=1e-12)
    assert closest_reading(ranges, -math.pi / 2, math.pi / 2) == pytest.approx(
        (1.0, -math.pi / 2))
    assert closest_reading([math.inf], 0.0, 0.1) is None


def test_level_points_undoes_a_pitched_scanner():
    # Pitched down by 0.2 rad, a wall 2 m ahead in the scan plane is lower than the sensor.
    point = level_points(np.array([[2.0, 0.0]]), 0.0, 0.2)[0]
    assert point == pytest.approx([2 * math.cos(0.2), 0.0, -2 * math.sin(0.2)])
    nearest = closest_horizontal(level_points(np.array([[3.0, 0.0], [0.0, 1.0]]), 0.1, 0.0))
    assert nearest[0] == pytest.approx(0.0)
    assert closest_horizontal(np.zeros((0, 3))) is None
