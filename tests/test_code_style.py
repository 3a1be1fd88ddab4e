"""pkgtool's own code keeps the project's flake8 standard (line length 99)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def test_pkgtool_tests_and_bench_are_flake8_clean() -> None:
    done = subprocess.run(
        [sys.executable, "-m", "flake8", "--isolated", "--max-line-length", "99",
         "--select", "E,F,W,C90", "--extend-ignore", "W503,W504",
         "--exclude", "fixtures", "pkgtool", "tests", "bench", "scripts"],
        cwd=ROOT, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stdout + done.stderr
