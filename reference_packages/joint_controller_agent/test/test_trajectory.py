# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""Trajectory building and the demo poses, without ROS communication."""

import math

from joint_controller_agent.humanoid_joint_controller import DEFAULT_JOINTS, wave_positions
from joint_controller_agent.trajectory import duration_from_seconds, single_point_trajectory
import pytest


@pytest.mark.parametrize(('seconds', 'sec', 'nanosec'), [
    (0.0, 0, 0),
    (1.5, 1, 500_000_000),
    (2.0, 2, 0),
    (0.9999999999, 1, 0),
    (0.25, 0, 250_000_000),
])
def test_duration_from_seconds(seconds, sec, nanosec):
    duration = duration_from_seconds(seconds)
    assert (duration.sec, duration.nanosec) == (sec, nanosec)


@pytest.mark.parametrize('seconds', [-0.1, math.nan, math.inf])
def test_duration_rejects_invalid_times(seconds):
    with pytest.raises(ValueError):
        duration_from_seconds(seconds)


def test_single_point_trajectory():
    msg = single_point_trajectory(['a', 'b'], [1, -0.5], 1.5)
    assert msg.joint_names == ['a', 'b']
    assert len(msg.points) == 1
    assert list(msg.points[0].positions) == [1.0, -0.5]
    assert (msg.points[0].time_from_start.sec, msg.points[0].time_from_start.nanosec) == (
        1, 500_000_000)


def test_position_count_must_match_joint_count():
    with pytest.raises(ValueError, match='1 positions given for 2 joints'):
        single_point_trajectory(['a', 'b'], [0.0], 1.0)


def test_wave_raises_the_right_arm_by_name():
    positions = dict(zip(DEFAULT_JOINTS, wave_positions(DEFAULT_JOINTS)))
    assert positions['right_shoulder_joint'] == -1.0
    assert positions['right_elbow_joint'] == -0.5
    assert sum(abs(p) for p in positions.values()) == 1.5


def test_wave_with_other_joint_names_is_all_zero():
    assert wave_positions(['neck_joint']) == [0.0]
