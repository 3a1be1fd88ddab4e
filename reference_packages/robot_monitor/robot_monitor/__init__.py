# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""Battery and temperature health monitors for a robot."""
