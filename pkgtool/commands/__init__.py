"""What each verb does, as functions that return frozen results and never print or exit.

The CLI (``pkgtool/cli_<verb>.py``) renders a result and exits with its ``exit_code``.
"""

from __future__ import annotations

from enum import IntEnum

__all__ = ["ExitCode"]


class ExitCode(IntEnum):
    """Process exit codes shared by every verb."""

    OK = 0
    """Nothing failed (warnings and info findings allowed unless strict)."""
    FINDINGS = 1
    """At least one finding at a failing level."""
    USAGE = 2
    """Bad command line or configuration, or a path that does not exist."""
    INTERNAL = 3
    """pkgtool itself failed (a rule or the package reader raised)."""
