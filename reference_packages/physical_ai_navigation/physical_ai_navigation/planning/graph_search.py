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
A* and Dijkstra on an 8-connected grid.

Both are best-first searches over the same graph; A* adds the octile-distance heuristic, which
never overestimates, so both return a shortest path. Diagonal moves may not cut corners.
"""

import heapq
import math

import numpy as np
from physical_ai_navigation.planning.grid_map import Cell

_SQRT2 = math.sqrt(2.0)
_MOVES = ((-1, 0, 1.0), (1, 0, 1.0), (0, -1, 1.0), (0, 1, 1.0),
          (-1, -1, _SQRT2), (-1, 1, _SQRT2), (1, -1, _SQRT2), (1, 1, _SQRT2))


def octile_distance(a: Cell, b: Cell) -> float:
    """Return the length of the shortest 8-connected path between two cells on an empty grid."""
    dr, dc = abs(a[0] - b[0]), abs(a[1] - b[1])
    return max(dr, dc) + (_SQRT2 - 1.0) * min(dr, dc)


def _neighbours(free: np.ndarray, cell: Cell):
    rows, cols = free.shape
    row, col = cell
    for dr, dc, cost in _MOVES:
        r, c = row + dr, col + dc
        if 0 <= r < rows and 0 <= c < cols and free[r, c]:
            if dr and dc and not (free[row, c] and free[r, col]):
                continue  # a diagonal step would clip the corner of an obstacle
            yield (r, c), cost


def _search(free: np.ndarray, start: Cell, goal: Cell, use_heuristic: bool) -> list[Cell] | None:
    if not (free[start] and free[goal]):
        return None
    best = {start: 0.0}
    parent: dict[Cell, Cell] = {}
    frontier = [(0.0, 0, start)]
    counter = 0
    while frontier:
        _, _, cell = heapq.heappop(frontier)
        if cell == goal:
            path = [cell]
            while path[-1] != start:
                path.append(parent[path[-1]])
            return path[::-1]
        for nxt, cost in _neighbours(free, cell):
            g = best[cell] + cost
            if g < best.get(nxt, math.inf):
                best[nxt], parent[nxt] = g, cell
                counter += 1
                h = octile_distance(nxt, goal) if use_heuristic else 0.0
                heapq.heappush(frontier, (g + h, counter, nxt))
    return None


def astar(free: np.ndarray, start: Cell, goal: Cell) -> list[Cell] | None:
    """Return a shortest cell path from ``start`` to ``goal`` (both included), or None."""
    return _search(free, start, goal, use_heuristic=True)


def dijkstra(free: np.ndarray, start: Cell, goal: Cell) -> list[Cell] | None:
    """Return a shortest cell path expanding uniformly by cost (no heuristic), or None."""
    return _search(free, start, goal, use_heuristic=False)


def path_length(path) -> float:
    """Return the length of a cell path in cells."""
    points = np.asarray(path, dtype=float)
    return float(np.linalg.norm(np.diff(points, axis=0), axis=1).sum()) if len(points) else 0.0
