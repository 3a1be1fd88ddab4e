# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""Sector geometry from angle_min/angle_increment, for every scan layout."""

import math

import pytest
from scans import LAYOUTS, make_scan
from simple_avoidance_agent.sectors import (
    is_valid_range, nearest_in_sectors, normalize_angle, Sector, symmetric_sector)

FRONT = symmetric_sector('front', 15.0)
LEFT = Sector('left', math.radians(20.0), math.radians(60.0))
RIGHT = Sector('right', math.radians(-60.0), math.radians(-20.0))


@pytest.mark.parametrize(('angle', 'expected'), [
    (0.0, 0.0),
    (2 * math.pi, 0.0),
    (math.radians(359.0), math.radians(-1.0)),
    (-math.pi, math.pi),
    (3 * math.pi, math.pi),
])
def test_normalize_angle(angle, expected):
    assert normalize_angle(angle) == pytest.approx(expected, abs=1e-9)


@pytest.mark.parametrize('reading', [math.inf, -math.inf, math.nan, 0.05, 10.5])
def test_invalid_readings(reading):
    assert not is_valid_range(reading, 0.12, 10.0)


def test_range_limits_are_valid():
    assert is_valid_range(0.12, 0.12, 10.0) and is_valid_range(10.0, 0.12, 10.0)


@pytest.mark.parametrize(('name', 'angle_min', 'increment', 'count'), LAYOUTS)
def test_each_obstacle_lands_in_its_sector(name, angle_min, increment, count):
    scan = make_scan(angle_min, increment, count,
                     obstacles=((0.0, 1.0, 0.5), (40.0, 1.0, 1.5), (-40.0, 1.0, 2.5)))
    nearest = nearest_in_sectors(scan, [FRONT, LEFT, RIGHT])
    assert nearest == {'front': 0.5, 'left': 1.5, 'right': 2.5}, name


@pytest.mark.parametrize(('name', 'angle_min', 'increment', 'count'), LAYOUTS)
def test_empty_sector_reports_infinity(name, angle_min, increment, count):
    nearest = nearest_in_sectors(make_scan(angle_min, increment, count), [FRONT])
    assert nearest == {'front': math.inf}, name


def test_behind_the_robot_is_not_in_front():
    scan = make_scan(0.0, 1.0, 360, obstacles=((180.0, 20.0, 0.3),))
    assert nearest_in_sectors(scan, [FRONT])['front'] == math.inf


def test_invalid_readings_inside_a_sector_are_ignored():
    scan = make_scan(-90.0, 1.0, 181)
    ranges = list(scan.ranges)
    ranges[88:93] = [math.nan, 0.0, -math.inf, 42.0, 0.9]
    scan.ranges = ranges
    assert nearest_in_sectors(scan, [FRONT])['front'] == pytest.approx(0.9)
