"""``pkgtool --help`` stays fast: heavy libraries load only when a command needs them.

Each check runs in a fresh interpreter, since this test process has imported everything.
"""

from __future__ import annotations

import subprocess
import sys

import pytest

HEAVY = ("lxml", "rich", "jinja2", "pydantic")

PROBE = """
import sys
from pkgtool import cli
cli._register()
try:
    cli.app({args!r})
except SystemExit:
    pass
print("LOADED:", *(m for m in {heavy!r} if m in sys.modules))
"""


def _loaded(*args: str) -> list[str]:
    code = PROBE.format(args=list(args), heavy=HEAVY)
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          check=True, timeout=60)
    return done.stdout.rpartition("LOADED:")[2].split()


@pytest.mark.parametrize("args", [["--help"], ["lint", "--help"], ["--version"]])
def test_help_loads_no_heavy_library(args: list[str]) -> None:
    assert _loaded(*args) == []


def test_importing_the_lint_modules_loads_no_heavy_library() -> None:
    code = ("import sys, pkgtool.cli_lint, pkgtool.commands.lint, pkgtool.config, "
            "pkgtool.workspace, pkgtool.report, pkgtool.docs_gen\n"
            f"print(' '.join(m for m in {HEAVY!r} if m in sys.modules))")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          check=True, timeout=60)
    assert done.stdout.split() == []
