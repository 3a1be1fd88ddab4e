# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""
Convert sensor_msgs/Image to and from numpy arrays (a replacement for cv_bridge).

cv_bridge from PyPI is a ROS 1 port that fails under NumPy 2, so the conversions the agent
needs live here. Arrays are (height, width) for one channel, (height, width, channels)
otherwise, in the byte order of this machine; row padding (``step``) is honoured.
"""

import sys

import numpy as np
from sensor_msgs.msg import Image
from std_msgs.msg import Header

# encoding -> (numpy dtype, channels), for the encodings of sensor_msgs/image_encodings.hpp.
ENCODINGS: dict[str, tuple[str, int]] = {
    'mono8': ('u1', 1), '8UC1': ('u1', 1),
    'bgr8': ('u1', 3), 'rgb8': ('u1', 3), '8UC3': ('u1', 3),
    'bgra8': ('u1', 4), 'rgba8': ('u1', 4), '8UC4': ('u1', 4),
    'mono16': ('u2', 1), '16UC1': ('u2', 1),
    '32FC1': ('f4', 1),
}


def _layout(encoding: str) -> tuple[np.dtype, int]:
    try:
        dtype, channels = ENCODINGS[encoding]
    except KeyError:
        raise ValueError(f'unsupported image encoding {encoding!r}') from None
    return np.dtype(dtype), channels


def image_to_array(msg: Image) -> np.ndarray:
    """Return a writable copy of the pixels of ``msg``."""
    dtype, channels = _layout(msg.encoding)
    row_bytes = msg.width * channels * dtype.itemsize
    if msg.step < row_bytes or len(msg.data) < msg.step * msg.height:
        raise ValueError(f'{msg.width}x{msg.height} {msg.encoding} image needs step >= '
                         f'{row_bytes} and {row_bytes * msg.height} bytes of data')
    data = np.frombuffer(msg.data, dtype=np.uint8, count=msg.step * msg.height)
    rows = data.reshape(msg.height, msg.step)[:, :row_bytes]
    order = '>' if msg.is_bigendian else '<'
    pixels = np.ascontiguousarray(rows).view(dtype.newbyteorder(order))
    shape = (msg.height, msg.width) if channels == 1 else (msg.height, msg.width, channels)
    return pixels.reshape(shape).astype(dtype.newbyteorder('='))


def array_to_image(array: np.ndarray, encoding: str, header: Header | None = None) -> Image:
    """Return an Image holding ``array``, which must match ``encoding``'s type and channels."""
    dtype, channels = _layout(encoding)
    expected_ndim = 2 if channels == 1 else 3
    if array.dtype != dtype or array.ndim != expected_ndim or (
            channels > 1 and array.shape[2] != channels):
        raise ValueError(f'{encoding} needs a {dtype} array with {channels} channel(s), '
                         f'not {array.dtype} of shape {array.shape}')
    pixels = np.ascontiguousarray(array)
    msg = Image()
    if header is not None:
        msg.header = header
    msg.height, msg.width = pixels.shape[:2]
    msg.encoding = encoding
    msg.is_bigendian = sys.byteorder == 'big'
    msg.step = msg.width * channels * dtype.itemsize
    msg.data = pixels.tobytes()
    return msg


def image_to_bgr8(msg: Image) -> np.ndarray:
    """Return ``msg`` as a (height, width, 3) BGR uint8 array, converting colour images."""
    pixels = image_to_array(msg)
    if msg.encoding in ('bgr8', '8UC3'):
        return pixels
    if msg.encoding == 'rgb8':
        return np.ascontiguousarray(pixels[:, :, ::-1])
    if msg.encoding in ('bgra8', '8UC4'):
        return np.ascontiguousarray(pixels[:, :, :3])
    if msg.encoding == 'rgba8':
        return np.ascontiguousarray(pixels[:, :, 2::-1])
    if msg.encoding in ('mono8', '8UC1'):
        return np.repeat(pixels[:, :, np.newaxis], 3, axis=2)
    raise ValueError(f'cannot show a {msg.encoding} image as bgr8')
