"""``pkgtool add``: what each operation writes, that it lints clean, and that it is idempotent."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from typer.testing import CliRunner

from pkgtool.cli import _register, app
from pkgtool.model.installed import installed_data
from pkgtool.model.package import load_package
from tests.add.conftest import created, strict_findings

_register()
YEAR = {"SOURCE_DATE_EPOCH": "1767225600"}  # 2026-01-01


def _add(*args: str, cwd: Path | None = None):  # type: ignore[no-untyped-def]
    old = Path.cwd()
    try:
        if cwd:
            os.chdir(cwd)
        return CliRunner().invoke(app, ["add", *args], env=YEAR)
    finally:
        os.chdir(old)


def _snapshot(root: Path) -> dict[str, bytes]:
    return {p.relative_to(root).as_posix(): p.read_bytes()
            for p in sorted(root.rglob("*")) if p.is_file()}


def test_add_node_writes_registers_and_lints_clean(package: Path) -> None:
    result = _add("node", "caller:client:std_srvs/srv/SetBool", str(package))
    assert result.exit_code == 0, result.output
    assert "new     grow/caller.py" in result.output
    assert "edited  setup.py" in result.output and "edited  package.xml" in result.output
    model = load_package(package)
    assert "caller = grow.caller:main" in [e.spec for e in model.setup_py.console_scripts]
    assert model.manifest.depends({"exec_depend"}) >= {"std_srvs", "rclpy"}
    assert (package / "test" / "test_caller.py").is_file()
    assert strict_findings(package) == []
    before = _snapshot(package)
    again = _add("node", "caller:client:std_srvs/srv/SetBool", str(package))
    assert again.exit_code == 0 and "Nothing to change" in again.output
    assert _snapshot(package) == before


def test_dry_run_prints_a_diff_and_writes_nothing(package: Path) -> None:
    before = _snapshot(package)
    result = _add("node", "beat:timer", "--dry-run", cwd=package)
    assert result.exit_code == 0, result.output
    assert "--- /dev/null\n+++ b/grow/beat.py" in result.output
    assert "+            'beat = grow.beat:main'," in result.output
    assert _snapshot(package) == before


def test_add_launch_then_config_then_a_node_joins_both(package: Path) -> None:
    assert _add("launch", str(package)).exit_code == 0
    config = _add("config", str(package))
    assert config.exit_code == 0, config.output
    assert "Pass config/params.yaml to the nodes" in config.output
    node = _add("node", "listener:subscriber", str(package))
    assert node.exit_code == 0, node.output
    launch = (package / "launch" / "grow.launch.py").read_text()
    assert "executable='talker'" in launch and "executable='listener'" in launch
    params = (package / "config" / "params.yaml").read_text()
    assert "talker:\n  ros__parameters:\n    topic: chatter\n    period: 0.5\n" in params
    installed = installed_data(load_package(package))
    assert installed["share/grow/launch/grow.launch.py"] == "launch/grow.launch.py"
    assert installed["share/grow/config/params.yaml"] == "config/params.yaml"
    assert load_package(package).manifest.depends({"exec_depend"}) >= {"launch", "launch_ros"}
    assert strict_findings(package) == []
    before = _snapshot(package)
    for args in (["launch"], ["config"], ["node", "listener:subscriber"]):
        assert _add(*args, str(package)).exit_code == 0
    assert _snapshot(package) == before


def test_a_node_added_to_a_launch_file_with_parameters_gets_its_block(tmp_path: Path) -> None:
    package = created(tmp_path, launch=True, config=True)
    assert _add("node", "listener:subscriber", str(package)).exit_code == 0
    launch = (package / "launch" / "grow.launch.py").read_text()
    assert launch.count("parameters=[params]") == 2
    assert "listener:\n  ros__parameters:\n    topic: chatter\n" in \
        (package / "config" / "params.yaml").read_text()
    assert strict_findings(package) == []


def test_add_dependency_maps_modules_to_rosdep_keys(package: Path) -> None:
    result = _add("dependency", "numpy", "sensor_msgs", "python3-yaml", "--path", str(package))
    assert result.exit_code == 0, result.output
    manifest = load_package(package).manifest
    assert manifest.depends({"exec_depend"}) >= {"python3-numpy", "sensor_msgs", "python3-yaml"}
    assert "<depend>sensor_msgs</depend>" in (package / "package.xml").read_text()
    tests = _add("dependency", "--test", "pytest", "hypothesis", "--path", str(package))
    assert tests.exit_code == 0, tests.output
    assert load_package(package).manifest.depends({"test_depend"}) >= {"python3-hypothesis"}
    assert [f for f in strict_findings(package) if not f.startswith("DEP006")] == []


@pytest.mark.parametrize(("args", "message"), [
    (["node", "bad-name:timer"], "Invalid node name"),
    (["node", "x1:teleporter"], "Unknown node kind"),
    (["node", "conftest:timer"], "taken by a generated test file"),
    (["dependency", "os"], "standard library"),
    (["dependency", "opencv-python"], "python3-opencv"),
    (["dependency", "grow"], "this package itself"),
    (["launch", "--name", "bringup.py"], "does not end in"),
])
def test_clear_refusals_change_nothing(package: Path, args: list[str], message: str) -> None:
    before = _snapshot(package)
    where = ["--path", str(package)] if args[0] == "dependency" else [str(package)]
    result = _add(*args, *where)
    assert result.exit_code == 2
    assert message in result.output
    assert _snapshot(package) == before


def test_a_setup_py_it_cannot_extend_is_refused_with_the_reason(package: Path) -> None:
    setup = package / "setup.py"
    setup.write_text(setup.read_text().replace(
        "entry_points={", "entry_points=dict(extra(), **{").replace("    },\n)", "    }),\n)"))
    before = _snapshot(package)
    result = _add("node", "beat:timer", str(package))
    assert result.exit_code == 2
    assert "setup.py computes the entry points" in result.output and "line" in result.output
    assert _snapshot(package) == before


def test_not_a_package_and_a_foreign_conftest_are_refused(tmp_path: Path, package: Path) -> None:
    assert "has no package.xml and setup.py" in _add("node", "a1:timer", str(tmp_path)).output
    (package / "test" / "conftest.py").write_text("import pytest\n")
    result = _add("node", "beat:timer", str(package))
    assert result.exit_code == 2 and "no `ros` fixture" in result.output


def test_create_force_into_a_package_registers_its_new_nodes(tmp_path: Path) -> None:
    package = created(tmp_path)
    result = CliRunner().invoke(app, [
        "create", "grow", "--destination-directory", str(tmp_path), "--force",
        "--node", "listener:subscriber", "--launch", "--maintainer-name", "Jane Doe",
        "--maintainer-email", "jane@example.com"], env=YEAR)
    assert result.exit_code == 0, result.output
    assert "setup.py  (edited)" in result.output
    scripts = [e.name for e in load_package(package).setup_py.console_scripts]
    assert scripts == ["talker", "listener"]
    assert "executable='listener'" in (package / "launch" / "grow.launch.py").read_text()
    assert strict_findings(package) == []
