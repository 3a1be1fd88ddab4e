"""Run real ``colcon build`` / ``colcon test`` in a workspace, isolated from the network.

Used by ``pkgtool reference``, ``pkgtool test`` and ``pkgtool grade`` and by the tests. Sources are
never written to: builds go to the workspace's build/install/log folders, bytecode is off.
"""

from __future__ import annotations

import os
import subprocess
import sys
import time
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path

from pkgtool.records import record
from pkgtool.ros.isolation import isolated_ros_env


@record
class ColconRun:
    """The outcome of one colcon invocation."""

    command: tuple[str, ...]
    returncode: int
    output: str
    seconds: float
    timed_out: bool = False
    limit: str | None = None
    """The sandbox limit that ended the run, e.g. ``timed out after 60 s`` (None: none hit)."""
    channel: bytes = b""
    """What the command wrote to its private results descriptor (sandboxed runs only)."""

    @property
    def ok(self) -> bool:
        """True when colcon exited 0 within its time limit."""
        return self.returncode == 0 and not self.timed_out


def colcon_executable() -> str:
    """The colcon script of the running interpreter's environment."""
    candidate = Path(sys.executable).parent / "colcon"
    return str(candidate) if candidate.exists() else "colcon"


Runner = Callable[[Sequence[str], Path, Mapping[str, str], float], ColconRun]
"""Runs ``(command, cwd, env, timeout)``: a plain subprocess by default, sandboxed by grade."""


def colcon_env(workspace: Path, *, domain_id: int, extra: Mapping[str, str] | None = None,
               base: Mapping[str, str] | None = None) -> dict[str, str]:
    """Environment for colcon and the tests it runs: isolated ROS, this venv's ROS on the paths.

    ``base`` replaces os.environ as the starting point (grading passes a scrubbed one).
    """
    log_dir = workspace / "ros_log"
    log_dir.mkdir(parents=True, exist_ok=True)
    env = isolated_ros_env(domain_id=domain_id, log_dir=str(log_dir), discovery_range="LOCALHOST",
                           base=base)
    prefix = sys.prefix
    for key in ("AMENT_PREFIX_PATH", "CMAKE_PREFIX_PATH"):
        parts = [p for p in env.get(key, "").split(os.pathsep) if p]
        env[key] = os.pathsep.join([prefix] + [p for p in parts if p != prefix])
    env["PATH"] = os.pathsep.join([str(Path(sys.executable).parent), env.get("PATH", "")])
    env["PYTHONDONTWRITEBYTECODE"] = "1"
    env["COLCON_HOME"] = str(workspace / ".colcon")
    env.pop("PYTHONPATH", None)
    env.update(extra or {})
    return env


def _run(args: Sequence[str], workspace: Path, env: Mapping[str, str], timeout: float,
         runner: Runner | None = None) -> ColconRun:
    command = (colcon_executable(), "--log-base", str(workspace / "log"), *args)
    if runner is not None:
        return runner(command, workspace, env, timeout)
    start = time.monotonic()
    try:
        done = subprocess.run(command, cwd=workspace, env=dict(env), stdin=subprocess.DEVNULL,
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                              errors="replace", timeout=timeout, check=False)
    except subprocess.TimeoutExpired as expired:
        out = expired.stdout or ""
        text = out.decode(errors="replace") if isinstance(out, bytes) else out
        return ColconRun(command, -9, text, time.monotonic() - start, timed_out=True)
    return ColconRun(command, done.returncode, done.stdout, time.monotonic() - start)


def _paths(workspace: Path) -> tuple[str, ...]:
    return ("--build-base", str(workspace / "build"), "--install-base", str(workspace / "install"))


def colcon_build(workspace: Path, *, base_paths: Sequence[Path], env: Mapping[str, str],
                 packages: Sequence[str] = (), timeout: float = 600.0,
                 symlink_install: bool = False, runner: Runner | None = None) -> ColconRun:
    """``colcon build`` of the packages under ``base_paths`` (all, or ``packages`` and deps)."""
    args = ["build", "--base-paths", *map(str, base_paths), *_paths(workspace),
            "--event-handlers", "console_direct+"]
    if symlink_install:
        args.append("--symlink-install")
    if packages:
        args += ["--packages-up-to", *packages]
    return _run(args, workspace, env, timeout, runner)


def colcon_test(workspace: Path, *, base_paths: Sequence[Path], env: Mapping[str, str],
                packages: Sequence[str] = (), timeout: float = 600.0,
                pytest_args: Sequence[str] = (), runner: Runner | None = None) -> ColconRun:
    """``colcon test`` with pytest's own output, failing when a test fails.

    ``pytest_args`` are passed on to pytest (``--pytest-args``).
    """
    args = ["test", "--base-paths", *map(str, base_paths), *_paths(workspace),
            "--event-handlers", "console_direct+", "--return-code-on-test-failure"]
    if packages:
        args += ["--packages-select", *packages]
    if pytest_args:  # colcon reads a leading space as "not an option of mine"
        args += ["--pytest-args", *(f" {a}" if a.startswith("-") else a for a in pytest_args)]
    return _run(args, workspace, env, timeout, runner)
