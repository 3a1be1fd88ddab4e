# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""Lab 2.1: stop and turn when an obstacle is ahead, otherwise drive forward."""

from sensor_msgs.msg import LaserScan
from simple_avoidance_agent.policy import Command, simple_command
from simple_avoidance_agent.scan_agent import run, ScanAgent
from simple_avoidance_agent.sectors import nearest_in_sectors, symmetric_sector


class AvoidanceAgent(ScanAgent):
    """Watch a sector straight ahead (+-``front_half_angle_deg``) for close obstacles."""

    def __init__(self, **kwargs) -> None:
        super().__init__('avoidance_agent', **kwargs)
        half_width = self.declare_parameter('front_half_angle_deg', 15.0).value
        self.front = symmetric_sector('front', half_width)

    def decide(self, scan: LaserScan) -> Command:
        """Turn when the front sector holds an obstacle closer than the threshold."""
        front = nearest_in_sectors(scan, [self.front])['front']
        return simple_command(front, self.threshold_distance, self.linear_speed,
                              self.angular_speed)


def main(args: list[str] | None = None) -> None:
    """Run the avoidance agent until interrupted."""
    run(AvoidanceAgent, args)


if __name__ == '__main__':
    main()
