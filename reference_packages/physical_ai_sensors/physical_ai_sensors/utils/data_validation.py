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

"""Validate sensor messages before processing them; each check lists what is wrong."""

import math

import numpy as np
from physical_ai_sensors.sensors.camera_utils import ENCODINGS
from sensor_msgs.msg import Image, Imu, LaserScan

_NANOSECONDS_PER_SECOND = 1_000_000_000


def _finite(*values: float) -> bool:
    return all(math.isfinite(v) for v in values)


def stamp_problems(stamp) -> list[str]:
    """Return what is wrong with a builtin_interfaces/Time stamp."""
    if stamp.sec < 0 or not 0 <= stamp.nanosec < _NANOSECONDS_PER_SECOND:
        return ['timestamp is negative or malformed']
    return []


def imu_problems(msg: Imu) -> list[str]:
    """
    Return what is wrong with an IMU message (an empty list when it is valid).

    Following REP 145, ``orientation_covariance[0] == -1`` means the sensor provides no
    orientation; the quaternion is then not checked.
    """
    problems = stamp_problems(msg.header.stamp)
    q = msg.orientation
    if msg.orientation_covariance[0] != -1.0:
        if not _finite(q.x, q.y, q.z, q.w):
            problems.append('orientation has NaN or infinite values')
        elif not 0.99 < math.sqrt(q.x ** 2 + q.y ** 2 + q.z ** 2 + q.w ** 2) < 1.01:
            problems.append('orientation quaternion is not normalised')
    acc, gyro = msg.linear_acceleration, msg.angular_velocity
    if not _finite(acc.x, acc.y, acc.z, gyro.x, gyro.y, gyro.z):
        problems.append('acceleration or angular velocity has NaN or infinite values')
    return problems


def validate_imu_message(imu_msg: Imu) -> bool:
    """Return True when the IMU message can be processed."""
    return not imu_problems(imu_msg)


def scan_problems(msg: LaserScan) -> list[str]:
    """Return what is wrong with a LaserScan (an empty list when it is valid)."""
    problems = stamp_problems(msg.header.stamp)
    if not _finite(msg.angle_min, msg.angle_max, msg.angle_increment) or (
            msg.angle_increment == 0.0
            or (msg.angle_max - msg.angle_min) * msg.angle_increment < 0.0):
        problems.append('angle_min, angle_max and angle_increment are inconsistent')
    elif len(msg.ranges) != round((msg.angle_max - msg.angle_min) / msg.angle_increment) + 1:
        problems.append('number of ranges does not match the angle range')
    if not 0.0 <= msg.range_min < msg.range_max:
        problems.append('range_min must be non-negative and below range_max')
    if len(msg.intensities) not in (0, len(msg.ranges)):
        problems.append('intensities and ranges differ in length')
    return problems


def image_problems(msg: Image) -> list[str]:
    """Return what is wrong with an Image (an empty list when it is valid)."""
    problems = stamp_problems(msg.header.stamp)
    if msg.encoding not in ENCODINGS:
        return problems + [f'unsupported encoding {msg.encoding!r}']
    dtype_name, channels = ENCODINGS[msg.encoding]
    if msg.width == 0 or msg.height == 0:
        problems.append('image is empty')
    elif msg.step < msg.width * channels * np.dtype(dtype_name).itemsize:
        problems.append('step is smaller than width times pixel size')
    elif len(msg.data) != msg.step * msg.height:
        problems.append('data length differs from step * height')
    return problems
