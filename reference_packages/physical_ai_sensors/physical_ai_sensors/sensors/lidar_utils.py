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

"""Lidar utilities: clean, filter and convert sensor_msgs/LaserScan ranges (numpy only)."""

import numpy as np


def clean_ranges(ranges, range_min: float, range_max: float) -> np.ndarray:
    """Return the ranges with NaN and values outside [range_min, range_max] set to +inf."""
    data = np.asarray(ranges, dtype=float)
    valid = np.isfinite(data) & (data >= range_min) & (data <= range_max)
    return np.where(valid, data, np.inf)


def median_filter(ranges, window: int) -> np.ndarray:
    """Return the running median over an odd ``window`` (edges repeat the end values)."""
    data = np.asarray(ranges, dtype=float)
    if window < 1 or window % 2 == 0:
        raise ValueError('window must be a positive odd number')
    if window == 1 or len(data) == 0:
        return data.copy()
    padded = np.pad(data, window // 2, mode='edge')
    return np.median(np.lib.stride_tricks.sliding_window_view(padded, window), axis=1)


def downsample(ranges, factor: int) -> np.ndarray:
    """Keep the nearest reading of each block of ``factor`` beams (conservative for obstacles)."""
    data = np.asarray(ranges, dtype=float)
    if factor < 1:
        raise ValueError('factor must be at least 1')
    if factor == 1:
        return data.copy()
    padded = np.pad(data, (0, -len(data) % factor), constant_values=np.inf)
    return padded.reshape(-1, factor).min(axis=1)


def beam_angles(count: int, angle_min: float, angle_increment: float) -> np.ndarray:
    """Return the angle of each of ``count`` beams."""
    return angle_min + angle_increment * np.arange(count)


def scan_to_points(ranges, angle_min: float, angle_increment: float) -> np.ndarray:
    """Return the finite readings as (N, 2) x, y points in the scanner frame."""
    data = np.asarray(ranges, dtype=float)
    angles = beam_angles(len(data), angle_min, angle_increment)
    finite = np.isfinite(data)
    return np.column_stack([data[finite] * np.cos(angles[finite]),
                            data[finite] * np.sin(angles[finite])])


def closest_reading(ranges, angle_min: float,
                    angle_increment: float) -> tuple[float, float] | None:
    """Return (distance, angle) of the nearest finite reading, or None when there is none."""
    data = np.asarray(ranges, dtype=float)
    finite = np.flatnonzero(np.isfinite(data))
    if len(finite) == 0:
        return None
    index = finite[np.argmin(data[finite])]
    return float(data[index]), float(angle_min + angle_increment * index)
