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

"""Plan in world coordinates: pick a planner, inflate obstacles, convert cells to metres."""

from physical_ai_navigation.planning.graph_search import astar, dijkstra
from physical_ai_navigation.planning.grid_map import GridMap, inflate
from physical_ai_navigation.planning.rrt import rrt

PLANNERS = {'astar': astar, 'dijkstra': dijkstra, 'rrt': rrt}
"""Planner name -> function(free_mask, start_cell, goal_cell) returning cell points or None."""


class PlanningError(ValueError):
    """No path could be planned; the message says why."""


def plan_path(grid: GridMap, start: tuple[float, float], goal: tuple[float, float], *,
              planner: str = 'astar', robot_radius: float = 0.0, occupied_threshold: int = 50,
              allow_unknown: bool = False) -> list[tuple[float, float]]:
    """
    Return world (x, y) waypoints from ``start`` to ``goal`` that keep ``robot_radius`` clear.

    Raises PlanningError when the planner is unknown, an end lies outside the map or in an
    (inflated) obstacle, or no path exists.
    """
    if planner not in PLANNERS:
        raise PlanningError(f'unknown planner {planner!r}; use one of {sorted(PLANNERS)}')
    start_cell, goal_cell = grid.world_to_cell(*start), grid.world_to_cell(*goal)
    if start_cell is None or goal_cell is None:
        raise PlanningError('start or goal lies outside the map')
    free = inflate(grid.free_mask(occupied_threshold, allow_unknown),
                   robot_radius / grid.resolution)
    if not free[start_cell]:
        raise PlanningError('start is inside an obstacle or too close to one')
    if not free[goal_cell]:
        raise PlanningError('goal is inside an obstacle or too close to one')
    cells = PLANNERS[planner](free, start_cell, goal_cell)
    if cells is None:
        raise PlanningError('no collision-free path exists')
    return [grid.cell_to_world(row, col) for row, col in cells]
