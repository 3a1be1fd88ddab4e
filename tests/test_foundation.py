"""The installable skeleton: console script, light core dependencies, locked ROS pins."""

from __future__ import annotations

import re
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

from pkgtool import __version__
from pkgtool.ros.isolation import isolated_ros_env

ROOT = Path(__file__).resolve().parent.parent
PYPROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text())


def _pkgtool(*args: str) -> subprocess.CompletedProcess[str]:
    script = Path(sys.executable).parent / "pkgtool"
    return subprocess.run([str(script), *args], capture_output=True, text=True, timeout=60)


def test_version_and_help_work() -> None:
    assert _pkgtool("--version").stdout.strip() == f"pkgtool {__version__}"
    help_run = _pkgtool("--help")
    assert help_run.returncode == 0
    assert "ament_python" in help_run.stdout


def test_core_dependencies_pull_no_ros_and_no_colcon() -> None:
    core = PYPROJECT["project"]["dependencies"]
    assert not [d for d in core if re.match(r"(ros-|colcon|rclpy|setuptools)", d)]
    assert "ros-jazzy-rclpy==7.1.6" in PYPROJECT["project"]["optional-dependencies"]["ros"]


def test_lock_pins_every_package_and_the_measured_ros_versions() -> None:
    lines = [ln.strip() for ln in (ROOT / "requirements" / "lock.txt").read_text().splitlines()
             if ln.strip() and not ln.lstrip().startswith("#")]
    assert lines and all("==" in ln for ln in lines), [ln for ln in lines if "==" not in ln]
    pins = dict(ln.split("==", 1) for ln in lines)
    assert pins["ros-jazzy-rclpy"] == "7.1.6"
    assert pins["ros-jazzy-rmw-fastrtps-cpp"] == "8.4.3"
    assert pins["colcon-common-extensions"] == "0.3.0"
    assert pins["setuptools"] == "68.1.2"


def test_lint_core_imports_without_ros() -> None:
    blocker = (
        "import sys\n"
        "class Block:\n"
        "    def find_spec(self, name, path=None, target=None):\n"
        "        if name.split('.')[0] in ('rclpy', 'colcon_core', 'rosidl_runtime_py'):\n"
        "            raise ImportError('ROS is not installed here')\n"
        "sys.meta_path.insert(0, Block())\n"
        "from pkgtool.engine import check_package\n"
        "from pkgtool.model.package import load_package\n"
        "from pkgtool.rules.registry import load_all\n"
        "print(len(load_all()))\n"
    )
    done = subprocess.run([sys.executable, "-c", blocker], capture_output=True, text=True,
                          timeout=60, cwd=ROOT)
    assert done.returncode == 0, done.stderr
    assert int(done.stdout) > 0


def test_isolation_refuses_the_default_discovery_range() -> None:
    with pytest.raises(ValueError):
        isolated_ros_env(domain_id=1, log_dir="/tmp", discovery_range="SUBNET")
    parent = {"RMW_IMPLEMENTATION": "x", "_ROS_WHEELS_BOOTSTRAP_COMPLETE": "1"}
    env = isolated_ros_env(domain_id=7, log_dir="/tmp/x", base=parent)
    assert env["ROS_AUTOMATIC_DISCOVERY_RANGE"] == "LOCALHOST"
    assert env["ROS_DOMAIN_ID"] == "7" and env["ROS_LOG_DIR"] == "/tmp/x"
    assert "RMW_IMPLEMENTATION" not in env and "_ROS_WHEELS_BOOTSTRAP_COMPLETE" not in env


def test_a_skipped_oracle_test_is_reported_as_failed(tmp_path: Path) -> None:
    (tmp_path / "test_oracle.py").write_text(
        "import pytest\n\n\n@pytest.mark.oracle\ndef test_x():\n    pytest.skip('no data')\n\n\n"
        "def test_plain():\n    pytest.skip('fine')\n")
    done = subprocess.run([sys.executable, "-m", "pytest", "-p", "tests.conftest", "-q",
                           "-o", "markers=oracle", "-p", "no:cacheprovider", "--rootdir",
                           str(tmp_path), str(tmp_path / "test_oracle.py")],
                          cwd=ROOT, capture_output=True, text=True, timeout=120)
    assert done.returncode == 1, done.stdout + done.stderr
    assert "1 failed, 1 skipped" in done.stdout, done.stdout
    assert "oracle test skipped" in done.stdout
