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
Camera utilities: sensor_msgs/Image <-> numpy conversion and simple image statistics.

cv_bridge is not used: the conversion is a reshape of the message buffer, which also works
where cv_bridge is unavailable or incompatible with NumPy 2.
"""

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

_LUMA = {'rgb8': (0.299, 0.587, 0.114), 'rgba8': (0.299, 0.587, 0.114),
         'bgr8': (0.114, 0.587, 0.299), 'bgra8': (0.114, 0.587, 0.299),
         '8UC3': (0.114, 0.587, 0.299)}


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


def to_grayscale(array: np.ndarray, encoding: str) -> np.ndarray:
    """Return a float grayscale image scaled to [0, 1] (floats are passed through)."""
    data = np.asarray(array, dtype=float)
    if data.ndim == 3:
        weights = _LUMA.get(encoding, (1 / 3, 1 / 3, 1 / 3))
        data = data[:, :, :3] @ np.array(weights)
    if encoding.startswith('32F'):
        return data
    return data / float(np.iinfo(ENCODINGS[encoding][0]).max)


def mean_brightness(array: np.ndarray, encoding: str) -> float:
    """Return the mean brightness in [0, 1]."""
    return float(np.mean(to_grayscale(array, encoding)))


def sharpness(gray: np.ndarray) -> float:
    """Return the variance of the discrete Laplacian: low values mean a blurred image."""
    g = np.asarray(gray, dtype=float)
    if g.shape[0] < 3 or g.shape[1] < 3:
        return 0.0
    laplacian = (g[:-2, 1:-1] + g[2:, 1:-1] + g[1:-1, :-2] + g[1:-1, 2:] - 4 * g[1:-1, 1:-1])
    return float(laplacian.var())
