# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""Exercise 2.1: tell obstacles ahead, on the left and on the right apart."""

import math
import random

from sensor_msgs.msg import LaserScan
from simple_avoidance_agent.policy import advanced_command, Command
from simple_avoidance_agent.scan_agent import run, ScanAgent
from simple_avoidance_agent.sectors import nearest_in_sectors, Sector, symmetric_sector


class AdvancedAvoidanceAgent(ScanAgent):
    """Narrow front sector plus left (positive angles) and right (negative angles) sectors."""

    def __init__(self, rng: random.Random | None = None, **kwargs) -> None:
        super().__init__('advanced_avoidance_agent', **kwargs)
        front_half = self.declare_parameter('front_half_angle_deg', 10.0).value
        side = math.radians(self.declare_parameter('side_angle_deg', 45.0).value)
        self.sectors = [
            symmetric_sector('front', front_half),
            Sector('left', 0.0, side),
            Sector('right', -side, 0.0),
        ]
        self.rng = rng or random.Random()

    def decide(self, scan: LaserScan) -> Command:
        """Pick the command from the nearest obstacle in each sector."""
        nearest = nearest_in_sectors(scan, self.sectors)
        return advanced_command(nearest['front'], nearest['left'], nearest['right'],
                                self.threshold_distance, self.linear_speed,
                                self.angular_speed, self.rng)


def main(args: list[str] | None = None) -> None:
    """Run the advanced avoidance agent until interrupted."""
    run(AdvancedAvoidanceAgent, args)


if __name__ == '__main__':
    main()
