"""The configuration ament_flake8 and ament_pep257 use (ament_lint 0.17, ROS 2 Jazzy).

Kept here as data so that pkgtool reproduces their verdicts without a ROS installation.
"""

from __future__ import annotations

AMENT_DOCSTRING_IGNORE = ("D100", "D101", "D102", "D103", "D104", "D105", "D106", "D107",
                          "D203", "D212", "D404")
"""ament_pep257's "ament" convention: every pydocstyle code except these."""

AMENT_FLAKE8_ARGS = (
    "--max-line-length=99",
    "--import-order-style=google",
    "--extend-ignore=" + ",".join(["B902", "C816", *AMENT_DOCSTRING_IGNORE, "I202"]),
)
"""ament_flake8.ini as flake8 command-line options (plugins read theirs when parsed)."""


def style_checked_files(files: tuple[str, ...]) -> list[str]:
    """The .py files ament's linters check: not under folders starting with '.' or '_'."""
    return [f for f in files if f.endswith(".py")
            and not any(part.startswith((".", "_")) for part in f.split("/")[:-1])]
