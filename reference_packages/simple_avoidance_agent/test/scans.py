# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""LaserScan builders shared by the tests: any angle range, resolution and direction."""

import math

from sensor_msgs.msg import LaserScan

# (name, angle_min in degrees, angle_increment in degrees, beam count)
LAYOUTS = [
    ('full_circle_from_0', 0.0, 1.0, 360),
    ('full_circle_from_minus_pi', -180.0, 0.5, 720),
    ('front_half_180', -90.0, 1.0, 181),
    ('hokuyo_270', -135.0, 0.25, 1081),
    ('clockwise_from_pi', 180.0, -1.0, 360),
    ('coarse_10_degrees', -180.0, 10.0, 36),
]


def make_scan(angle_min_deg: float, increment_deg: float, count: int,
              obstacles: tuple = (), fill: float = math.inf) -> LaserScan:
    """Return a scan reading ``fill`` everywhere except at ``(angle_deg, width_deg, range)``."""
    scan = LaserScan()
    scan.header.frame_id = 'base_scan'
    scan.angle_min = math.radians(angle_min_deg)
    scan.angle_increment = math.radians(increment_deg)
    scan.angle_max = scan.angle_min + (count - 1) * scan.angle_increment
    scan.range_min = 0.12
    scan.range_max = 10.0
    ranges = [fill] * count
    for angle_deg, width_deg, distance in obstacles:
        for index in range(count):
            beam = angle_min_deg + index * increment_deg
            offset = (beam - angle_deg + 180.0) % 360.0 - 180.0
            if abs(offset) <= width_deg / 2.0:
                ranges[index] = distance
    scan.ranges = ranges
    return scan
