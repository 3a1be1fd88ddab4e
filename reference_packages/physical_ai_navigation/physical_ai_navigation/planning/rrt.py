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

"""RRT: a sampling-based planner, with greedy shortcutting of the path it finds."""

import numpy as np
from physical_ai_navigation.planning.grid_map import Cell, segment_is_free


def shortcut(free: np.ndarray, points: list) -> list:
    """Return the path with every waypoint skipped that a straight free segment can bypass."""
    result = [points[0]]
    index = 0
    while index < len(points) - 1:
        furthest = index + 1
        for candidate in range(len(points) - 1, index + 1, -1):
            if segment_is_free(free, points[index], points[candidate]):
                furthest = candidate
                break
        result.append(points[furthest])
        index = furthest
    return result


def rrt(free: np.ndarray, start: Cell, goal: Cell, *, seed: int = 0, step: float = 3.0,
        goal_bias: float = 0.1, max_iterations: int = 5000) -> list | None:
    """
    Return a collision-free path of (row, col) points from ``start`` to ``goal``, or None.

    The tree grows by at most ``step`` cells towards random samples (the goal itself with
    probability ``goal_bias``); the result is shortcut and is not shortest. ``seed`` makes the
    result reproducible.
    """
    if not (free[start] and free[goal]):
        return None
    rng = np.random.default_rng(seed)
    rows, cols = free.shape
    nodes = np.array([start], dtype=float)
    parents = [-1]
    target = np.array(goal, dtype=float)
    for _ in range(max_iterations):
        sample = target if rng.random() < goal_bias else rng.random(2) * [rows - 1, cols - 1]
        nearest = int(np.argmin(np.linalg.norm(nodes - sample, axis=1)))
        direction = sample - nodes[nearest]
        distance = float(np.linalg.norm(direction))
        if distance == 0.0:
            continue
        new = nodes[nearest] + direction * min(1.0, step / distance)
        if not segment_is_free(free, nodes[nearest], new):
            continue
        nodes = np.vstack([nodes, new])
        parents.append(nearest)
        if np.linalg.norm(target - new) <= step and segment_is_free(free, new, target):
            path = [tuple(target)]
            index = len(nodes) - 1
            while index != -1:
                path.append(tuple(nodes[index]))
                index = parents[index]
            return shortcut(free, path[::-1])
    return None
