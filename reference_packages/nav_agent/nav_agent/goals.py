# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""Goal poses and result classification for NavigateToPose (pure, no ROS runtime)."""

from enum import Enum
import math

from action_msgs.msg import GoalStatus
from geometry_msgs.msg import Quaternion


class Outcome(Enum):
    """How a navigation request ended, from the agent's point of view."""

    SUCCEEDED = 'succeeded'
    ABORTED = 'aborted'
    CANCELED = 'canceled'
    REJECTED = 'rejected'
    SERVER_UNAVAILABLE = 'server unavailable'
    TIMED_OUT = 'timed out'
    UNKNOWN = 'unknown'


# GoalStatus comes from action_msgs.msg: rclpy's ActionClient has no GoalStatus attribute.
_TERMINAL = {
    GoalStatus.STATUS_SUCCEEDED: Outcome.SUCCEEDED,
    GoalStatus.STATUS_ABORTED: Outcome.ABORTED,
    GoalStatus.STATUS_CANCELED: Outcome.CANCELED,
}


def outcome_for_status(status: int) -> Outcome:
    """Map a final action_msgs/GoalStatus value to an Outcome."""
    return _TERMINAL.get(status, Outcome.UNKNOWN)


def yaw_to_quaternion(yaw_degrees: float) -> Quaternion:
    """Return the rotation of ``yaw_degrees`` about +z (counter-clockwise seen from above)."""
    half = math.radians(yaw_degrees) / 2.0
    return Quaternion(x=0.0, y=0.0, z=math.sin(half), w=math.cos(half))
