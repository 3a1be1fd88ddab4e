# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""An agent that sends navigation goals to Nav2's NavigateToPose action server."""
