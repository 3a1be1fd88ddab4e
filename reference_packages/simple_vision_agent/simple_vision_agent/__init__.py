# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""A perception agent: find coloured objects in sensor_msgs/Image streams."""
