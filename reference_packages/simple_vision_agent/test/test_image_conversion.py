# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""sensor_msgs/Image <-> numpy without cv_bridge (broken under NumPy 2)."""

import sys

import numpy as np
import pytest
from sensor_msgs.msg import Image
from simple_vision_agent.image_conversion import (
    array_to_image, ENCODINGS, image_to_array, image_to_bgr8)
from std_msgs.msg import Header

RNG = np.random.default_rng(0)


def _random(encoding: str, height: int = 5, width: int = 7) -> np.ndarray:
    dtype, channels = ENCODINGS[encoding]
    shape = (height, width) if channels == 1 else (height, width, channels)
    if dtype == 'f4':
        return RNG.random(shape, dtype=np.float32)
    return RNG.integers(0, np.iinfo(dtype).max, size=shape, dtype=dtype)


@pytest.mark.parametrize('encoding', sorted(ENCODINGS))
def test_round_trip(encoding):
    array = _random(encoding)
    header = Header(frame_id='camera')
    msg = array_to_image(array, encoding, header=header)
    assert (msg.height, msg.width, msg.encoding, msg.header.frame_id) == (5, 7, encoding,
                                                                          'camera')
    assert msg.step * msg.height == len(msg.data)
    back = image_to_array(msg)
    assert back.dtype == array.dtype and back.shape == array.shape
    np.testing.assert_array_equal(back, array)
    back[0, 0] = 0  # the result is a writable copy


def test_rgb8_is_reordered_to_bgr():
    msg = array_to_image(np.array([[[10, 20, 30]]], dtype=np.uint8), 'rgb8')
    assert image_to_bgr8(msg).tolist() == [[[30, 20, 10]]]


def test_rgba8_and_bgra8_lose_alpha():
    pixel = np.array([[[10, 20, 30, 255]]], dtype=np.uint8)
    assert image_to_bgr8(array_to_image(pixel, 'rgba8')).tolist() == [[[30, 20, 10]]]
    assert image_to_bgr8(array_to_image(pixel, 'bgra8')).tolist() == [[[10, 20, 30]]]


def test_mono8_becomes_grey_bgr():
    msg = array_to_image(np.array([[7, 200]], dtype=np.uint8), 'mono8')
    assert image_to_bgr8(msg).tolist() == [[[7, 7, 7], [200, 200, 200]]]


def test_row_padding_is_skipped():
    msg = Image(height=2, width=2, encoding='mono8', step=4)
    msg.data = bytes([1, 2, 99, 99, 3, 4, 99, 99])
    assert image_to_array(msg).tolist() == [[1, 2], [3, 4]]


def test_big_endian_data_is_read_correctly():
    msg = Image(height=1, width=2, encoding='16UC1', step=4, is_bigendian=True)
    msg.data = bytes([0x01, 0x02, 0xff, 0x00])
    values = image_to_array(msg)
    assert values.tolist() == [[0x0102, 0xff00]]
    assert values.dtype.byteorder in ('=', '|') or values.dtype.byteorder == (
        '<' if sys.byteorder == 'little' else '>')


def test_unsupported_encoding_is_a_value_error():
    with pytest.raises(ValueError, match='unsupported image encoding'):
        image_to_array(Image(height=1, width=1, encoding='yuv422', step=2, data=[0, 0]))


def test_truncated_data_is_a_value_error():
    with pytest.raises(ValueError, match='needs step'):
        image_to_array(Image(height=2, width=2, encoding='bgr8', step=6, data=[0] * 6))


def test_array_must_match_the_encoding():
    with pytest.raises(ValueError):
        array_to_image(np.zeros((2, 2), dtype=np.uint8), 'bgr8')
    with pytest.raises(ValueError):
        array_to_image(np.zeros((2, 2, 3), dtype=np.float64), 'bgr8')


def test_depth_images_cannot_be_shown_as_bgr():
    with pytest.raises(ValueError, match='cannot show'):
        image_to_bgr8(array_to_image(np.zeros((2, 2), dtype=np.float32), '32FC1'))
