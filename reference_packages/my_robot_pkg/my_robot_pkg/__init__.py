# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""Agents that observe and report the robot's state."""
