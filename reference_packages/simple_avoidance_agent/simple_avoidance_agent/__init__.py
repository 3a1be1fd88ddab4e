# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""Obstacle avoidance agents: LaserScan in, geometry_msgs/Twist out."""
