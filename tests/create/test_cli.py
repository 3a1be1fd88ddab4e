"""The ``pkgtool create`` command line: ros2 pkg create habits, exit codes, defaults."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from typer.testing import CliRunner

from pkgtool.cli import _register, app
from pkgtool.model.package import load_package
from tests.create.conftest import expected_files

_register()
MAINTAINER = ["--maintainer-name", "Jane Doe", "--maintainer-email", "jane@example.com"]


def _create(tmp_path: Path, *args: str, env: dict[str, str] | None = None):
    return CliRunner().invoke(app, ["create", *args, "--destination-directory", str(tmp_path)],
                              env=env)


def test_ros2_pkg_create_style_dependencies_and_node_name(tmp_path: Path) -> None:
    result = _create(tmp_path, "my_pkg", "--build-type", "ament_python", *MAINTAINER,
                     "--node-name", "my_node", "--library-name", "my_lib", "--dependencies",
                     "sensor_msgs", "numpy", "geometry_msgs,std_msgs")
    assert result.exit_code == 0, result.output
    assert "Created" in result.output and "my_node.py" in result.output
    manifest = load_package(tmp_path / "my_pkg").manifest
    assert manifest.depends({"depend"}) == {"geometry_msgs", "rclpy", "sensor_msgs", "std_msgs"}
    assert manifest.depends({"exec_depend"}) >= {"python3-numpy"}
    assert (tmp_path / "my_pkg" / "my_pkg" / "my_lib" / "__init__.py").is_file()


@pytest.mark.parametrize("args, message", [
    (["My-Pkg"], "Invalid package name `My-Pkg`"),
    (["my_pkg", "--license", "WTFPL"], "Choose one of: Apache-2.0, BSL-1.0"),
    (["my_pkg", "--node", "n1:teleporter"], "Unknown node kind `teleporter`"),
    (["my_pkg", "--build-type", "ament_cmake"], "ament_python packages only"),
    (["my_pkg", "other_pkg"], "Unexpected argument `other_pkg`"),
])
def test_refusals_exit_2_and_write_nothing(tmp_path: Path, args: list[str], message: str) -> None:
    result = _create(tmp_path, *args, *MAINTAINER)
    assert result.exit_code == 2
    assert message in result.output
    assert list(tmp_path.iterdir()) == []


def test_existing_destination_exits_2(tmp_path: Path) -> None:
    assert _create(tmp_path, "my_pkg", *MAINTAINER).exit_code == 0
    again = _create(tmp_path, "my_pkg", *MAINTAINER)
    assert again.exit_code == 2 and "already exists" in again.output
    forced = _create(tmp_path, "my_pkg", *MAINTAINER, "--force", "--node", "beat:timer")
    assert forced.exit_code == 0 and "existing kept" in forced.output


def test_dry_run_prints_the_tree(tmp_path: Path) -> None:
    result = _create(tmp_path, "my_pkg", *MAINTAINER, "--dry-run", "--node", "talker:publisher",
                     "--launch", "--config")
    assert result.exit_code == 0
    count = len(expected_files("my_pkg", ("talker:publisher",), launch=True, config=True))
    assert result.output.startswith(
        f"Would create `{tmp_path / 'my_pkg'}` ({count} files):\nmy_pkg/\n")
    assert "│   └── params.yaml" in result.output
    assert list(tmp_path.iterdir()) == []


def test_maintainer_defaults_come_from_git_and_the_year_from_source_date_epoch(
        tmp_path: Path) -> None:
    gitconfig = tmp_path / "gitconfig"
    gitconfig.write_text("[user]\n\tname = Grace Hopper\n\temail = grace@example.org\n")
    out = tmp_path / "out"
    env = {"GIT_CONFIG_GLOBAL": str(gitconfig), "GIT_CONFIG_NOSYSTEM": "1",
           "SOURCE_DATE_EPOCH": "946684800"}  # 2000-01-01
    result = _create(out, "my_pkg", "--node", "beat:timer", env=env)
    assert result.exit_code == 0, result.output
    manifest = load_package(out / "my_pkg").manifest
    assert (manifest.maintainers[0].name, manifest.maintainers[0].email) == (
        "Grace Hopper", "grace@example.org")
    header = (out / "my_pkg" / "my_pkg" / "beat.py").read_text().splitlines()[:2]
    assert header == ["# Copyright 2000 Grace Hopper", "# SPDX-License-Identifier: Apache-2.0"]
    explicit = _create(tmp_path / "y", "my_pkg", "--copyright-year", "2024", *MAINTAINER, env=env)
    assert "Copyright (c) 2024" not in (tmp_path / "y/my_pkg/LICENSE").read_text()  # Apache
    assert explicit.exit_code == 0
    assert (tmp_path / "y/my_pkg/setup.py").read_text().startswith("# Copyright 2024 Jane Doe")


def test_create_help_loads_neither_jinja2_nor_the_create_package() -> None:
    code = ("import sys\nfrom pkgtool import cli\ncli._register()\ntry:\n"
            "    cli.app(['create', '--help'])\nexcept SystemExit:\n    pass\n"
            "print('LOADED:', *(m for m in ('jinja2', 'pkgtool.create') if m in sys.modules))")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          check=True, timeout=60)
    assert done.stdout.rpartition("LOADED:")[2].split() == []


def test_help_names_the_argument_as_the_docs_do() -> None:
    result = CliRunner().invoke(app, ["create", "--help"])
    assert "Usage: pkgtool create [OPTIONS] {NAME}" in result.output
    assert "separated, repeatable." in " ".join(result.output.split())
