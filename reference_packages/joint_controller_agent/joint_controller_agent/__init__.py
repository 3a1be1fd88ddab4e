# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""A Python agent commanding humanoid joints through ROS 2 controllers."""
