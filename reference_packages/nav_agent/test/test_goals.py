# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""Goal orientation and status classification, without ROS communication."""

import math

from action_msgs.msg import GoalStatus
from nav_agent.goals import Outcome, outcome_for_status, yaw_to_quaternion
import pytest
from rclpy.action import ActionClient


@pytest.mark.parametrize(('yaw', 'z', 'w'), [
    (0.0, 0.0, 1.0),
    (90.0, math.sqrt(0.5), math.sqrt(0.5)),
    (-90.0, -math.sqrt(0.5), math.sqrt(0.5)),
    (180.0, 1.0, 0.0),
])
def test_yaw_to_quaternion(yaw, z, w):
    q = yaw_to_quaternion(yaw)
    assert (q.x, q.y) == (0.0, 0.0)
    assert (q.z, q.w) == pytest.approx((z, w), abs=1e-12)
    assert q.x ** 2 + q.y ** 2 + q.z ** 2 + q.w ** 2 == pytest.approx(1.0)


@pytest.mark.parametrize(('status', 'outcome'), [
    (GoalStatus.STATUS_SUCCEEDED, Outcome.SUCCEEDED),
    (GoalStatus.STATUS_ABORTED, Outcome.ABORTED),
    (GoalStatus.STATUS_CANCELED, Outcome.CANCELED),
    (GoalStatus.STATUS_EXECUTING, Outcome.UNKNOWN),
    (GoalStatus.STATUS_UNKNOWN, Outcome.UNKNOWN),
])
def test_outcome_for_status(status, outcome):
    assert outcome_for_status(status) is outcome


def test_seed_mistake_goal_status_is_not_an_action_client_attribute():
    # The lesson compared against ActionClient.GoalStatus.STATUS_SUCCEEDED, which raises
    # AttributeError in the result callback: GoalStatus lives in action_msgs.msg.
    assert not hasattr(ActionClient, 'GoalStatus')
    assert GoalStatus.STATUS_SUCCEEDED == 4
