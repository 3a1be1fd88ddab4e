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
Convert sensor_msgs/Image to and from numpy arrays without cv_bridge.

cv_bridge is not a dependency: its PyPI port fails under NumPy 2, and the conversion is only a
reshape of the message buffer that honours ``step`` padding and byte order.
"""

import cv2
import numpy as np
from sensor_msgs.msg import Image

ENCODINGS = {
    'mono8': ('uint8', 1), '8UC1': ('uint8', 1),
    'bgr8': ('uint8', 3), 'rgb8': ('uint8', 3), '8UC3': ('uint8', 3),
    'bgra8': ('uint8', 4), 'rgba8': ('uint8', 4),
    'mono16': ('uint16', 1), '16UC1': ('uint16', 1),
    '32FC1': ('float32', 1),
}
"""Supported encodings: (numpy dtype, channels)."""

_TO_BGR = {'bgr8': None, '8UC3': None, 'rgb8': cv2.COLOR_RGB2BGR, 'mono8': cv2.COLOR_GRAY2BGR,
           '8UC1': cv2.COLOR_GRAY2BGR, 'bgra8': cv2.COLOR_BGRA2BGR, 'rgba8': cv2.COLOR_RGBA2BGR}


def image_to_array(msg: Image) -> np.ndarray:
    """Return the image as an (H, W) or (H, W, C) array, a copy of the message data."""
    if msg.encoding not in ENCODINGS:
        raise ValueError(f'unsupported encoding {msg.encoding!r}')
    dtype_name, channels = ENCODINGS[msg.encoding]
    dtype = np.dtype(dtype_name).newbyteorder('>' if msg.is_bigendian else '<')
    row_bytes = msg.width * channels * dtype.itemsize
    if msg.step < row_bytes or len(msg.data) < msg.step * msg.height:
        raise ValueError('image data is shorter than height * step')
    buffer = np.frombuffer(bytes(msg.data), dtype=np.uint8)[:msg.step * msg.height]
    rows = buffer.reshape(msg.height, msg.step)[:, :row_bytes]
    array = np.ascontiguousarray(rows).view(dtype).astype(dtype.newbyteorder('='))
    shape = (msg.height, msg.width) if channels == 1 else (msg.height, msg.width, channels)
    return array.reshape(shape)


def array_to_image(array: np.ndarray, encoding: str, header=None) -> Image:
    """Return an Image message holding ``array`` in ``encoding`` (little endian, no padding)."""
    if encoding not in ENCODINGS:
        raise ValueError(f'unsupported encoding {encoding!r}')
    dtype_name, channels = ENCODINGS[encoding]
    data = np.ascontiguousarray(array, dtype=np.dtype(dtype_name).newbyteorder('<'))
    if data.ndim != (2 if channels == 1 else 3) or (channels > 1 and data.shape[2] != channels):
        raise ValueError(f'array of shape {data.shape} does not fit encoding {encoding!r}')
    msg = Image()
    if header is not None:
        msg.header = header
    msg.height, msg.width = int(data.shape[0]), int(data.shape[1])
    msg.encoding = encoding
    msg.is_bigendian = 0
    msg.step = msg.width * channels * data.itemsize
    msg.data = data.tobytes()
    return msg


def image_to_bgr(msg: Image) -> np.ndarray:
    """Return an 8-bit colour image as a BGR array, the layout OpenCV expects."""
    if msg.encoding not in _TO_BGR:
        raise ValueError(f'cannot convert {msg.encoding!r} to bgr8')
    array = image_to_array(msg)
    code = _TO_BGR[msg.encoding]
    return array if code is None else cv2.cvtColor(array, code)
