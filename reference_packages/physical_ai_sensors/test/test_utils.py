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

"""Unit tests of timestamp synchronisation and message validation."""

import math

from builtin_interfaces.msg import Time
from physical_ai_sensors.utils.data_validation import image_problems, scan_problems
from physical_ai_sensors.utils.timestamp_sync import (
    stamp_to_nanoseconds, stamp_to_seconds, TimestampSynchronizer)
import pytest
from sensor_msgs.msg import Image, Imu, LaserScan


def stamped(msg_type, seconds: float):
    msg = msg_type()
    msg.header.stamp = Time(sec=int(seconds), nanosec=round((seconds % 1) * 1e9))
    return msg


def valid_scan(count: int = 5) -> LaserScan:
    scan = stamped(LaserScan, 1.0)
    scan.angle_min, scan.angle_increment = -0.2, 0.1
    scan.angle_max = scan.angle_min + scan.angle_increment * (count - 1)
    scan.range_min, scan.range_max = 0.1, 10.0
    scan.ranges = [1.0] * count
    return scan


def test_stamp_conversions():
    stamp = Time(sec=3, nanosec=250_000_000)
    assert stamp_to_nanoseconds(stamp) == 3_250_000_000
    assert stamp_to_seconds(stamp) == pytest.approx(3.25)


def test_synchronizer_pairs_messages_within_slop():
    sync = TimestampSynchronizer(2, slop=0.05)
    assert sync.add(0, stamped(Imu, 1.00)) is None
    imu_late = stamped(Imu, 1.10)
    assert sync.add(0, imu_late) is None
    scan = stamped(LaserScan, 1.12)
    assert sync.add(1, scan) == (imu_late, scan)
    # Both messages and the older IMU sample were consumed.
    assert sync.add(1, stamped(LaserScan, 1.13)) is None


def test_synchronizer_rejects_messages_too_far_apart_and_bounds_queues():
    sync = TimestampSynchronizer(2, slop=0.01, queue_size=2)
    for second in range(5):
        assert sync.add(0, stamped(Imu, float(second))) is None
    assert sync.add(1, stamped(LaserScan, 0.0)) is None  # IMU at 0 s was dropped (queue of 2)
    assert sync.add(1, stamped(LaserScan, 4.005)) is not None
    with pytest.raises(ValueError):
        TimestampSynchronizer(1, 0.1)


def test_scan_validation():
    assert scan_problems(valid_scan()) == []
    scan = valid_scan()
    scan.ranges = [1.0] * 3
    assert scan_problems(scan) == ['number of ranges does not match the angle range']
    scan = valid_scan()
    scan.angle_increment = -0.1
    assert 'inconsistent' in scan_problems(scan)[0]
    scan = valid_scan()
    scan.range_min, scan.intensities = 20.0, [1.0]
    assert len(scan_problems(scan)) == 2
    scan = valid_scan()
    scan.angle_increment = math.nan
    assert scan_problems(scan)


def test_image_validation():
    image = stamped(Image, 2.0)
    image.height, image.width, image.encoding, image.step = 2, 3, 'bgr8', 9
    image.data = bytes(18)
    assert image_problems(image) == []
    image.step = 8
    assert image_problems(image) == ['step is smaller than width times pixel size']
    image.step, image.data = 9, bytes(17)
    assert image_problems(image) == ['data length differs from step * height']
    image.encoding = 'jpeg'
    assert image_problems(image) == ["unsupported encoding 'jpeg'"]
