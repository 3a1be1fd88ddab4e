# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""The pure decision rules of both agents."""

import math
import random

import pytest
from simple_avoidance_agent.policy import advanced_command, simple_command

SPEEDS = {'threshold': 0.7, 'linear_speed': 0.2, 'angular_speed': 0.5}


def test_simple_drives_forward_when_clear():
    command = simple_command(math.inf, **SPEEDS)
    assert (command.linear, command.angular, command.turning) == (0.2, 0.0, False)


def test_simple_turns_right_in_place_when_blocked():
    # The lesson says "Turn right" but published +0.5, a left turn (REP 103: +z is left).
    command = simple_command(0.3, **SPEEDS)
    assert command.linear == 0.0 and command.angular == -0.5


def test_threshold_itself_is_clear():
    assert not simple_command(0.7, **SPEEDS).turning


@pytest.mark.parametrize(('front', 'left', 'right', 'angular'), [
    (math.inf, 0.5, math.inf, -0.5),
    (math.inf, math.inf, 0.5, 0.5),
    (math.inf, 0.4, 0.6, -0.5),
    (math.inf, 0.6, 0.4, 0.5),
    (math.inf, math.inf, math.inf, 0.0),
])
def test_advanced_turns_away_from_side_obstacles(front, left, right, angular):
    command = advanced_command(front, left, right, rng=random.Random(0), **SPEEDS)
    assert command.angular == angular
    assert command.linear == (0.2 if angular == 0.0 else 0.0)


def test_advanced_turns_randomly_but_only_in_place_when_blocked_ahead():
    rng = random.Random(7)
    turns = {advanced_command(0.2, math.inf, math.inf, rng=rng, **SPEEDS).angular
             for _ in range(50)}
    assert turns == {-0.5, 0.5}
    assert advanced_command(0.2, 0.1, 0.1, rng=rng, **SPEEDS).linear == 0.0
