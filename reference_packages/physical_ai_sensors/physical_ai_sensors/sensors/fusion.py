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

"""Fuse lidar points with IMU tilt: express scan points in a gravity-levelled frame."""

import math

import numpy as np


def tilt_matrix(roll: float, pitch: float) -> np.ndarray:
    """Return the rotation Ry(pitch) @ Rx(roll) that levels a tilted sensor (yaw is kept)."""
    cr, sr, cp, sp = math.cos(roll), math.sin(roll), math.cos(pitch), math.sin(pitch)
    rx = np.array([[1.0, 0.0, 0.0], [0.0, cr, -sr], [0.0, sr, cr]])
    ry = np.array([[cp, 0.0, sp], [0.0, 1.0, 0.0], [-sp, 0.0, cp]])
    return ry @ rx


def level_points(points_xy: np.ndarray, roll: float, pitch: float) -> np.ndarray:
    """Return scan-plane points (N, 2) as (N, 3) points in the levelled frame."""
    points = np.asarray(points_xy, dtype=float).reshape(-1, 2)
    planar = np.column_stack([points, np.zeros(len(points))])
    return planar @ tilt_matrix(roll, pitch).T


def closest_horizontal(points: np.ndarray) -> np.ndarray | None:
    """Return the levelled point nearest in the horizontal plane, or None without points."""
    data = np.asarray(points, dtype=float).reshape(-1, 3)
    if len(data) == 0:
        return None
    return data[np.argmin(np.hypot(data[:, 0], data[:, 1]))]
