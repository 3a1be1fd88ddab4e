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

"""Pure pursuit path following and a scan check for obstacles ahead."""

import math

import numpy as np


def nearest_obstacle_ahead(ranges, angle_min: float, angle_increment: float,
                           half_angle: float) -> float:
    """
    Return the nearest valid range within ``half_angle`` of straight ahead (inf if none).

    Works for any scan: beams are selected by their angle, not by fixed indices.
    """
    data = np.asarray(ranges, dtype=float)
    angles = angle_min + angle_increment * np.arange(len(data))
    wrapped = np.arctan2(np.sin(angles), np.cos(angles))
    ahead = (np.abs(wrapped) <= half_angle) & np.isfinite(data) & (data > 0.0)
    return float(data[ahead].min()) if ahead.any() else math.inf


def pure_pursuit(pose: tuple[float, float, float], path, *, lookahead: float,
                 max_linear: float, max_angular: float,
                 goal_tolerance: float) -> tuple[float, float, bool]:
    """
    Return (linear, angular, goal_reached) velocities steering ``pose`` (x, y, yaw) along ``path``.

    The target is the first waypoint at least ``lookahead`` ahead of the nearest one; the robot
    drives the arc through it, slows down near the goal, and turns on the spot when the target
    is behind it.
    """
    points = np.asarray(path, dtype=float).reshape(-1, 2)
    x, y, yaw = pose
    if len(points) == 0:
        return 0.0, 0.0, True
    to_goal = float(np.hypot(*(points[-1] - (x, y))))
    if to_goal <= goal_tolerance:
        return 0.0, 0.0, True
    distances = np.hypot(points[:, 0] - x, points[:, 1] - y)
    nearest = int(np.argmin(distances))
    beyond = np.flatnonzero(distances[nearest:] >= lookahead)
    target = points[nearest + beyond[0]] if len(beyond) else points[-1]
    dx, dy = target[0] - x, target[1] - y
    local_x = math.cos(yaw) * dx + math.sin(yaw) * dy
    local_y = -math.sin(yaw) * dx + math.cos(yaw) * dy
    if local_x <= 0.0 and abs(local_y) < 1e-9:
        local_y = 1e-9  # straight behind: turn left
    if abs(math.atan2(local_y, local_x)) > math.pi / 2:
        return 0.0, math.copysign(max_angular, local_y), False
    linear = min(max_linear, to_goal)
    curvature = 2.0 * local_y / (local_x ** 2 + local_y ** 2)
    angular = max(-max_angular, min(max_angular, linear * curvature))
    return linear, angular, False
