# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""Build trajectory_msgs/JointTrajectory commands (no ROS runtime needed)."""

import math
from typing import Sequence

from builtin_interfaces.msg import Duration, Time
from trajectory_msgs.msg import JointTrajectory, JointTrajectoryPoint

NANOSECONDS_PER_SECOND = 1_000_000_000


def duration_from_seconds(seconds: float) -> Duration:
    """Return ``seconds`` as a Duration, carrying rounded nanoseconds into whole seconds."""
    if not math.isfinite(seconds) or seconds < 0.0:
        raise ValueError(f'time_from_start must be a finite, non-negative number, not {seconds}')
    sec, nanosec = divmod(round(seconds * NANOSECONDS_PER_SECOND), NANOSECONDS_PER_SECOND)
    return Duration(sec=sec, nanosec=nanosec)


def single_point_trajectory(joint_names: Sequence[str], positions: Sequence[float],
                            time_from_start_sec: float, stamp: Time | None = None
                            ) -> JointTrajectory:
    """Return a trajectory reaching ``positions`` (radians) after ``time_from_start_sec``."""
    if len(positions) != len(joint_names):
        raise ValueError(f'{len(positions)} positions given for {len(joint_names)} joints')
    point = JointTrajectoryPoint()
    point.positions = [float(p) for p in positions]
    point.time_from_start = duration_from_seconds(time_from_start_sec)
    msg = JointTrajectory()
    if stamp is not None:
        msg.header.stamp = stamp
    msg.joint_names = list(joint_names)
    msg.points = [point]
    return msg
