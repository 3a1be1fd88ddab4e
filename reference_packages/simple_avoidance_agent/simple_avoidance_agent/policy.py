# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""Turn nearest-obstacle distances into a velocity command (pure, no ROS)."""

from dataclasses import dataclass
import random


@dataclass(frozen=True)
class Command:
    """A planar velocity command: ``linear`` m/s forward, ``angular`` rad/s (positive = left)."""

    linear: float
    angular: float
    reason: str

    @property
    def turning(self) -> bool:
        """Return True when the command rotates the robot."""
        return self.angular != 0.0


def simple_command(front: float, threshold: float, linear_speed: float,
                   angular_speed: float) -> Command:
    """Stop and turn right when something is closer than ``threshold`` ahead, else drive on."""
    if front < threshold:
        # REP 103: positive angular.z turns left, so turning right needs a negative rate.
        return Command(0.0, -angular_speed, 'Obstacle detected! Turning right.')
    return Command(linear_speed, 0.0, 'Path clear, moving forward.')


def advanced_command(front: float, left: float, right: float, threshold: float,
                     linear_speed: float, angular_speed: float,
                     rng: random.Random) -> Command:
    """
    Avoid obstacles using the nearest distances ahead, to the left and to the right.

    Directly ahead: stop and turn in a random direction. On one side: turn away from it.
    On both sides: turn away from the nearer one. Nothing within ``threshold``: drive on.
    """
    if front < threshold:
        return Command(0.0, rng.choice([-angular_speed, angular_speed]),
                       'Obstacle directly in front! Stopping and turning randomly.')
    left_blocked, right_blocked = left < threshold, right < threshold
    if left_blocked and (not right_blocked or left <= right):
        return Command(0.0, -angular_speed, 'Obstacle on left! Turning right.')
    if right_blocked:
        return Command(0.0, angular_speed, 'Obstacle on right! Turning left.')
    return Command(linear_speed, 0.0, 'Path clear, moving forward.')
