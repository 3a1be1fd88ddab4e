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

"""An occupancy grid as numpy arrays, with world <-> cell conversion and obstacle inflation."""

from dataclasses import dataclass
import math

import numpy as np
from physical_ai_navigation.utils.geometry import pose_2d

Cell = tuple[int, int]
"""A grid cell as (row, column), i.e. (y index, x index)."""


@dataclass(frozen=True)
class GridMap:
    """
    Occupancy values (-1 unknown, 0 free to 100 occupied), row-major like nav_msgs/OccupancyGrid.

    ``origin`` is the world pose (x, y, yaw) of the corner of cell (0, 0); ``resolution`` is
    metres per cell.
    """

    data: np.ndarray
    resolution: float
    origin: tuple[float, float, float] = (0.0, 0.0, 0.0)

    @classmethod
    def from_msg(cls, msg) -> 'GridMap':
        """Build from a nav_msgs/OccupancyGrid."""
        info = msg.info
        if info.width * info.height != len(msg.data) or info.resolution <= 0.0:
            raise ValueError('occupancy grid size and data length disagree')
        data = np.asarray(msg.data, dtype=np.int16).reshape(info.height, info.width)
        return cls(data, float(info.resolution), pose_2d(info.origin))

    @property
    def shape(self) -> tuple[int, int]:
        """Rows and columns."""
        return self.data.shape

    def free_mask(self, occupied_threshold: int = 50, allow_unknown: bool = False) -> np.ndarray:
        """Return True where the robot may go."""
        free = (self.data >= 0) & (self.data < occupied_threshold)
        return free | (self.data < 0) if allow_unknown else free

    def world_to_cell(self, x: float, y: float) -> Cell | None:
        """Return the cell containing world point (x, y), or None outside the grid."""
        ox, oy, yaw = self.origin
        dx, dy = x - ox, y - oy
        local_x = math.cos(yaw) * dx + math.sin(yaw) * dy
        local_y = -math.sin(yaw) * dx + math.cos(yaw) * dy
        # The epsilon keeps points on a cell border (3.5 / 0.1 = 34.999...) in the upper cell.
        col = math.floor(local_x / self.resolution + 1e-9)
        row = math.floor(local_y / self.resolution + 1e-9)
        rows, cols = self.shape
        return (row, col) if 0 <= row < rows and 0 <= col < cols else None

    def cell_to_world(self, row: float, col: float) -> tuple[float, float]:
        """Return the world point at the centre of a (possibly fractional) cell."""
        ox, oy, yaw = self.origin
        local_x, local_y = (col + 0.5) * self.resolution, (row + 0.5) * self.resolution
        return (ox + math.cos(yaw) * local_x - math.sin(yaw) * local_y,
                oy + math.sin(yaw) * local_x + math.cos(yaw) * local_y)


def inflate(free: np.ndarray, radius_cells: float) -> np.ndarray:
    """Return ``free`` with every cell within ``radius_cells`` of a blocked cell blocked too."""
    blocked = ~np.asarray(free, dtype=bool)
    reach = int(math.floor(radius_cells))
    if reach <= 0:
        return ~blocked
    rows, cols = blocked.shape
    padded = np.pad(blocked, reach, constant_values=False)
    grown = blocked.copy()
    for dr in range(-reach, reach + 1):
        for dc in range(-reach, reach + 1):
            if dr * dr + dc * dc <= radius_cells * radius_cells:
                grown |= padded[reach + dr:reach + dr + rows, reach + dc:reach + dc + cols]
    return ~grown


def segment_cells(start, end) -> list[Cell]:
    """
    Return every cell the straight segment between two points touches, in order.

    Points are continuous (row, col) coordinates with cell centres at integers. Where the
    segment passes exactly through a cell corner, both side cells are included.
    """
    (r0, c0), (r1, c1) = (np.asarray(start, float) + 0.5), (np.asarray(end, float) + 0.5)
    row, col = math.floor(r0), math.floor(c0)
    last = (math.floor(r1), math.floor(c1))
    d_row, d_col = r1 - r0, c1 - c0
    step_r, step_c = (1 if d_row > 0 else -1), (1 if d_col > 0 else -1)
    next_r = ((row + (step_r > 0)) - r0) / d_row if d_row else math.inf
    next_c = ((col + (step_c > 0)) - c0) / d_col if d_col else math.inf
    delta_r = abs(1.0 / d_row) if d_row else math.inf
    delta_c = abs(1.0 / d_col) if d_col else math.inf
    cells = [(row, col)]
    for _ in range(abs(last[0] - row) + abs(last[1] - col)):
        if (row, col) == last:
            break
        if math.isclose(next_r, next_c):
            cells += [(row + step_r, col), (row, col + step_c)]
            row, next_r = row + step_r, next_r + delta_r
            col, next_c = col + step_c, next_c + delta_c
        elif next_r < next_c:
            row, next_r = row + step_r, next_r + delta_r
        else:
            col, next_c = col + step_c, next_c + delta_c
        cells.append((row, col))
    return cells


def segment_is_free(free: np.ndarray, start, end) -> bool:
    """Return True when every cell the straight segment between two points touches is free."""
    rows, cols = free.shape
    return all(0 <= r < rows and 0 <= c < cols and free[r, c]
               for r, c in segment_cells(start, end))
