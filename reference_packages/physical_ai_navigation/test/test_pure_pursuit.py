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

"""Unit tests of pure pursuit and the obstacle-ahead check."""

import math

from physical_ai_navigation.control.pure_pursuit import nearest_obstacle_ahead, pure_pursuit
import pytest

LIMITS = {'lookahead': 0.5, 'max_linear': 0.3, 'max_angular': 1.0, 'goal_tolerance': 0.1}
STRAIGHT = [(0.0, 0.0), (1.0, 0.0), (2.0, 0.0)]


def test_drives_straight_along_a_straight_path():
    linear, angular, reached = pure_pursuit((0.0, 0.0, 0.0), STRAIGHT, **LIMITS)
    assert (linear, angular, reached) == pytest.approx((0.3, 0.0, False))


def test_turns_towards_a_path_on_the_left():
    linear, angular, _ = pure_pursuit((0.0, -0.5, 0.0), STRAIGHT, **LIMITS)
    assert linear > 0 and angular > 0


def test_turns_on_the_spot_when_the_path_is_behind():
    linear, angular, _ = pure_pursuit((2.0, 0.0, 0.0), [(2.0, 0.0), (0.0, 0.0)], **LIMITS)
    assert linear == 0.0 and abs(angular) == 1.0


def test_slows_down_and_stops_at_the_goal():
    linear, _, reached = pure_pursuit((1.85, 0.0, 0.0), STRAIGHT, **LIMITS)
    assert linear == pytest.approx(0.15) and not reached
    assert pure_pursuit((1.95, 0.02, 0.0), STRAIGHT, **LIMITS) == (0.0, 0.0, True)
    assert pure_pursuit((0.0, 0.0, 0.0), [], **LIMITS) == (0.0, 0.0, True)


@pytest.mark.parametrize('angle_min,increment,count', [
    (-math.pi, math.pi / 180, 360),  # -180..179 degrees
    (0.0, math.pi / 360, 720),  # 0..360 degrees, front at index 0 and at the end
    (-math.pi / 4, math.pi / 8, 5),  # a narrow 90-degree sensor
])
def test_obstacle_ahead_is_found_for_any_scan_layout(angle_min, increment, count):
    ranges = [5.0] * count
    angles = [angle_min + increment * i for i in range(count)]
    ahead = min(range(count), key=lambda i: abs(math.atan2(math.sin(angles[i]),
                                                           math.cos(angles[i]))))
    ranges[ahead] = 0.3
    assert nearest_obstacle_ahead(ranges, angle_min, increment, 0.5) == pytest.approx(0.3)
    ranges[ahead] = math.inf
    assert nearest_obstacle_ahead(ranges, angle_min, increment, 0.5) == pytest.approx(5.0)


def test_obstacle_behind_is_ignored():
    ranges = [5.0] * 8
    ranges[4] = 0.2  # straight behind for a 0..2 pi scan
    assert nearest_obstacle_ahead(ranges, 0.0, math.pi / 4, 0.5) == 5.0
    assert nearest_obstacle_ahead([], 0.0, 0.1, 0.5) == math.inf
