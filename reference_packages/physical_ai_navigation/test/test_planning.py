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

"""Unit tests of the grid map and the A*, Dijkstra and RRT planners."""

import math

import numpy as np
from physical_ai_navigation.planning.graph_search import (
    astar, dijkstra, octile_distance, path_length)
from physical_ai_navigation.planning.grid_map import (
    GridMap, inflate, segment_cells, segment_is_free)
from physical_ai_navigation.planning.planners import plan_path, PlanningError
from physical_ai_navigation.planning.rrt import rrt
import pytest

SEARCHES = [astar, dijkstra]


def wall_with_gap(rows=20, cols=20, gap_row=16) -> np.ndarray:
    """Return a free grid with a wall at column 10, open only at ``gap_row``."""
    free = np.ones((rows, cols), dtype=bool)
    free[:, 10] = False
    free[gap_row, 10] = True
    return free


def test_world_cell_round_trip_with_an_offset_and_rotated_origin():
    grid = GridMap(np.zeros((10, 20), dtype=np.int16), 0.5, (-2.0, 1.0, math.pi / 2))
    assert grid.world_to_cell(*grid.cell_to_world(3, 7)) == (3, 7)
    x, y = grid.cell_to_world(0, 0)
    assert (x, y) == pytest.approx((-2.25, 1.25))
    assert grid.world_to_cell(5.0, 5.0) is None


def test_free_mask_thresholds_and_unknown_cells():
    grid = GridMap(np.array([[0, 49, 50, 100, -1]], dtype=np.int16), 1.0)
    assert grid.free_mask().tolist() == [[True, True, False, False, False]]
    assert grid.free_mask(allow_unknown=True).tolist() == [[True, True, False, False, True]]


def test_inflate_blocks_a_disc_around_obstacles():
    free = np.ones((7, 7), dtype=bool)
    free[3, 3] = False
    inflated = inflate(free, 1.5)
    assert (~inflated).sum() == 9  # the 3x3 block: corners are sqrt(2) < 1.5 away
    assert inflate(free, 0.0).tolist() == free.tolist()


def test_segment_cells_lists_every_touched_cell():
    assert segment_cells((0, 0), (0, 3)) == [(0, 0), (0, 1), (0, 2), (0, 3)]
    assert segment_cells((0, 0), (2, 2)) == [(0, 0), (1, 0), (0, 1), (1, 1), (2, 1), (1, 2),
                                             (2, 2)]
    assert segment_cells((0.0, 0.0), (1.0, 4.0)) == [(0, 0), (0, 1), (0, 2), (1, 2), (1, 3),
                                                     (1, 4)]
    assert segment_cells((2.2, 2.2), (2.3, 2.1)) == [(2, 2)]


def test_segment_is_free_rejects_a_segment_clipping_an_obstacle_corner():
    free = np.ones((5, 5), dtype=bool)
    free[1, 2] = False
    assert not segment_is_free(free, (0.0, 0.0), (2.0, 4.0))  # passes through cell (1, 2)
    assert segment_is_free(free, (3.0, 0.0), (3.0, 4.0))
    assert not segment_is_free(free, (3.0, 0.0), (3.0, 5.0))  # leaves the grid


@pytest.mark.parametrize('search', SEARCHES)
def test_shortest_path_on_an_empty_grid(search):
    path = search(np.ones((10, 10), dtype=bool), (0, 0), (9, 6))
    assert path[0] == (0, 0) and path[-1] == (9, 6)
    assert path_length(path) == pytest.approx(octile_distance((0, 0), (9, 6)))


@pytest.mark.parametrize('search', SEARCHES)
def test_path_goes_through_the_gap_without_cutting_corners(search, assert_path_free):
    free = wall_with_gap()
    path = search(free, (2, 2), (2, 17))
    assert (16, 10) in path
    assert_path_free(free, path)
    for (r1, c1), (r2, c2) in zip(path, path[1:]):
        assert max(abs(r1 - r2), abs(c1 - c2)) == 1
        assert free[r1, c2] and free[r2, c1]  # diagonal steps keep both side cells free


@pytest.mark.parametrize('seed', range(5))
def test_astar_and_dijkstra_agree_on_the_cost_in_cluttered_grids(seed, assert_path_free):
    free = wall_with_gap() & (np.random.default_rng(seed).random((20, 20)) > 0.2)
    free[2, 2] = free[2, 17] = True
    free[15:18, 9:12] = True
    a, d = astar(free, (2, 2), (2, 17)), dijkstra(free, (2, 2), (2, 17))
    assert (a is None) == (d is None)
    if a is not None:
        assert path_length(a) == pytest.approx(path_length(d))
        assert_path_free(free, a)


@pytest.mark.parametrize('planner', [astar, dijkstra, rrt])
def test_unreachable_or_blocked_goal_gives_none(planner):
    free = np.ones((10, 10), dtype=bool)
    free[:, 5] = False
    assert planner(free, (0, 0), (0, 9)) is None
    assert planner(free, (0, 0), (0, 5)) is None


def test_rrt_finds_a_collision_free_path_through_the_gap(assert_path_free):
    free = wall_with_gap(rows=30, cols=30, gap_row=25)
    path = rrt(free, (3, 3), (3, 26), seed=3)
    assert path is not None
    assert path[0] == (3, 3) and path[-1] == (3, 26)
    assert_path_free(free, path)
    assert rrt(free, (3, 3), (3, 26), seed=3) == path  # reproducible


@pytest.mark.parametrize('planner', ['astar', 'dijkstra', 'rrt'])
def test_plan_path_in_world_coordinates_keeps_the_robot_radius(planner, assert_path_free):
    data = np.zeros((20, 20), dtype=np.int16)
    data[:, 10] = 100
    data[12:18, 10] = 0  # a 6-cell (0.6 m) gap
    grid = GridMap(data, 0.1, (-1.0, -1.0, 0.0))
    points = plan_path(grid, (-0.75, -0.75), (0.75, -0.75), planner=planner, robot_radius=0.2)
    assert points[0] == pytest.approx((-0.75, -0.75))
    assert points[-1] == pytest.approx((0.75, -0.75))
    inflated = inflate(grid.free_mask(), 2.0)
    assert_path_free(inflated, [((y + 1.0) / 0.1 - 0.5, (x + 1.0) / 0.1 - 0.5) for x, y in points])


def test_plan_path_explains_failures():
    grid = GridMap(np.zeros((5, 5), dtype=np.int16), 1.0)
    with pytest.raises(PlanningError, match='unknown planner'):
        plan_path(grid, (0.5, 0.5), (3.5, 3.5), planner='bfs')
    with pytest.raises(PlanningError, match='outside'):
        plan_path(grid, (0.5, 0.5), (9.0, 3.5))
    blocked = GridMap(np.full((5, 5), 100, dtype=np.int16), 1.0)
    with pytest.raises(PlanningError, match='start'):
        plan_path(blocked, (0.5, 0.5), (3.5, 3.5))
