# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""
Nearest obstacle per angular sector of a LaserScan, for any angle range and resolution.

Angles follow REP 103: 0 is straight ahead (+x), positive angles are to the left (+y).
A beam's angle is ``angle_min + i * angle_increment``, normalised to (-pi, pi], so a scan
over [0, 2*pi), over [-pi, pi) or over a 180 degree window works the same way, whatever
its number of beams or the sign of its increment.
"""

from dataclasses import dataclass
import math
from typing import Iterator, Protocol, Sequence


class ScanLike(Protocol):
    """The fields of sensor_msgs/LaserScan that the sector logic reads."""

    angle_min: float
    angle_increment: float
    range_min: float
    range_max: float
    ranges: Sequence[float]


@dataclass(frozen=True)
class Sector:
    """An angular window ``[low, high]`` in radians, relative to straight ahead."""

    name: str
    low: float
    high: float

    def contains(self, angle: float) -> bool:
        """Return True when ``angle`` (normalised to (-pi, pi]) lies in the window."""
        return self.low <= angle <= self.high


def symmetric_sector(name: str, half_width_deg: float) -> Sector:
    """Return a sector centred on straight ahead, ``half_width_deg`` to each side."""
    half = math.radians(half_width_deg)
    return Sector(name, -half, half)


def normalize_angle(angle: float) -> float:
    """Map ``angle`` to (-pi, pi]."""
    wrapped = math.atan2(math.sin(angle), math.cos(angle))
    return math.pi if wrapped == -math.pi else wrapped


def is_valid_range(reading: float, range_min: float, range_max: float) -> bool:
    """Return True for a finite reading inside the scanner's [range_min, range_max]."""
    return math.isfinite(reading) and range_min <= reading <= range_max


def valid_beams(scan: ScanLike) -> Iterator[tuple[float, float]]:
    """Yield ``(angle, range)`` for each valid beam; inf, nan and out-of-range are skipped."""
    for index, reading in enumerate(scan.ranges):
        if is_valid_range(reading, scan.range_min, scan.range_max):
            yield normalize_angle(scan.angle_min + index * scan.angle_increment), reading


def nearest_in_sectors(scan: ScanLike, sectors: Sequence[Sector]) -> dict[str, float]:
    """Return the nearest valid range in each sector, ``math.inf`` when it saw nothing."""
    nearest = {sector.name: math.inf for sector in sectors}
    for angle, reading in valid_beams(scan):
        for sector in sectors:
            if sector.contains(angle) and reading < nearest[sector.name]:
                nearest[sector.name] = reading
    return nearest
