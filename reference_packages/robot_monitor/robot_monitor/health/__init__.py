# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""Pure models behind the monitor nodes: simulated sensors and status classification."""
