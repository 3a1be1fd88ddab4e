"""The lint core on the oldest Python pkgtool supports (3.10: Ubuntu 22.04, ROS 2 Humble).

pkgtool is installed from a copy of the source into a fresh Python 3.10 virtual environment,
with the newest dependencies that Python takes, and lints every rule fixture: its JSON report is
the same, byte for byte, as this environment's. An AST class or a standard library name that
3.10 lacks (``ast.TryStar`` is 3.11's) fails here, not on a Humble user's machine.
"""

from __future__ import annotations

import glob
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from tests.helpers import copy_project_sources

pytestmark = pytest.mark.slow
ROOT = Path(__file__).resolve().parents[2]
UV = str(Path(sys.executable).parent / "uv")  # the project's installer (scripts/bootstrap.sh)
OLDEST = "3.10"


def _oldest_python() -> str | None:
    """A Python 3.10 interpreter of this machine: on PATH, or one pyenv installed."""
    found = shutil.which(f"python{OLDEST}")
    pyenv = sorted(glob.glob(str(Path.home() / f".pyenv/versions/{OLDEST}.*/bin/python{OLDEST}")))
    return pyenv[-1] if pyenv else found


def _run(*args: str, cwd: Path) -> str:
    done = subprocess.run(args, cwd=cwd, capture_output=True, text=True, timeout=600,
                          check=False)
    assert done.returncode == 0, done.stdout + done.stderr
    return done.stdout


def _lint(pkgtool: str, cwd: Path) -> str:
    """The JSON report of every fixture; SYN007 aside, which notes what the Python running
    pkgtool cannot parse (it differs by design)."""
    return _run(pkgtool, "lint", "--no-cache", "--isolated", "--exit-zero", "--format", "json",
                "--ignore", "SYN007", str(ROOT / "tests" / "fixtures"), cwd=cwd)


def test_lint_on_python_3_10_reports_what_it_reports_here(tmp_path: Path) -> None:
    python = _oldest_python()
    if python is None:
        pytest.skip(f"no Python {OLDEST} on this machine")
    source = copy_project_sources(tmp_path / "src")
    venv = tmp_path / "venv"
    _run(UV, "venv", "-q", "--python", python, str(venv), cwd=tmp_path)
    _run(UV, "pip", "install", "-q", "--python", str(venv / "bin" / "python"), str(source),
         cwd=tmp_path)
    assert _run(str(venv / "bin" / "python"), "-c", "import sys; print(sys.version[:4])",
                cwd=tmp_path).strip() == OLDEST
    assert _lint(str(venv / "bin" / "pkgtool"), tmp_path) == \
        _lint(str(Path(sys.executable).parent / "pkgtool"), tmp_path)
