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

"""Small pose helpers shared by the planner, the follower and the grid map."""

import math


def yaw_from_quaternion(q) -> float:
    """Return the rotation about z (radians) of a geometry_msgs/Quaternion-like object."""
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


def pose_2d(pose) -> tuple[float, float, float]:
    """Return (x, y, yaw) of a geometry_msgs/Pose."""
    return pose.position.x, pose.position.y, yaw_from_quaternion(pose.orientation)
