"""``pkgtool doctor``: one ok/missing line per check, with the command that fixes each."""

from __future__ import annotations

import os
import subprocess
import sys
from importlib import metadata
from pathlib import Path

import pytest

from pkgtool.commands import doctor

PKGTOOL = str(Path(sys.executable).parent / "pkgtool")


def _doctor(**env: str | None) -> dict[str, list[str]]:
    """Run the real command; return each check's lines by check name."""
    environ = {k: v for k, v in {**os.environ, **env}.items() if v is not None}
    done = subprocess.run([PKGTOOL, "doctor"], env=environ, capture_output=True, text=True,
                          timeout=180)
    assert done.returncode == 0, done.stdout + done.stderr
    lines: dict[str, list[str]] = {}
    name = ""
    for line in done.stdout.splitlines()[:-1]:
        if not line.startswith(" "):
            name = line.split()[1]
        lines.setdefault(name, []).append(line)
    assert done.stdout.splitlines()[-1].endswith("missing.")
    return lines


@pytest.mark.ros
def test_this_machine_real_rclpy_and_an_unsafe_shell() -> None:
    """rclpy really initialises here; a shell without a discovery range gets the fix."""
    lines = _doctor(ROS_AUTOMATIC_DISCOVERY_RANGE=None, RMW_IMPLEMENTATION="rmw_cyclonedds_cpp")
    assert lines["python"][0].startswith("ok ")
    assert lines["rclpy"][0].startswith("ok ") and "initialises" in lines["rclpy"][0]
    assert lines["rmw"][0].startswith("missing") and "rmw_fastrtps_cpp" in lines["rmw"][0]
    assert lines["rmw"][1].split() == ["fix:", "unset", "RMW_IMPLEMENTATION"]
    assert lines["discovery"][0].startswith("missing")
    assert lines["discovery"][1].split() == ["fix:", "export",
                                             "ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST"]
    for name in ("extra", "colcon", "ament_flake8", "ament_pep257", "grade"):
        assert lines[name][0].startswith("ok "), lines[name]
    assert lines["ament_copyright"][0].startswith("missing")  # no wheel exists
    assert "apt install ros-jazzy-ament-copyright" in lines["ament_copyright"][1]


@pytest.mark.ros
def test_a_safe_shell_is_ok() -> None:
    lines = _doctor(ROS_AUTOMATIC_DISCOVERY_RANGE="LOCALHOST", RMW_IMPLEMENTATION=None)
    assert len(lines["discovery"]) == 1 and lines["discovery"][0].startswith("ok ")
    assert lines["rmw"][0].startswith("ok ")


def test_a_missing_extra_names_what_is_missing_and_how_to_install_it(
        monkeypatch: pytest.MonkeyPatch) -> None:
    real = metadata.version

    def version(name: str) -> str:
        if name == "flake8":
            raise metadata.PackageNotFoundError(name)
        return real(name)

    monkeypatch.setattr(doctor.metadata, "version", version)
    style = next(c for c in doctor._python() if c.name == "extra [style]")
    assert not style.ok and "missing flake8==7.5.0" in style.detail
    assert style.fix == f"{sys.executable} -m pip install flake8==7.5.0"


def test_the_install_command_fits_the_installer(tmp_path: Path,
                                                monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(doctor.sys, "prefix", str(tmp_path))
    assert doctor.install_command(["a==1", "b>=2"]) == (
        f"{sys.executable} -m pip install a==1 'b>=2'")
    monkeypatch.setattr(doctor.importlib.util, "find_spec", lambda name: None)  # no pip
    assert doctor.install_command(["a==1"]) == f"uv pip install --python {sys.executable} a==1"
    (tmp_path / "pipx_metadata.json").write_text("{}")
    assert doctor.install_command(["a==1"]) == "pipx inject pkgtool-ros a==1"
