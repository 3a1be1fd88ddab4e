"""The ``pkgtool create`` command line: ros2 pkg create habits, exit codes, defaults."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from typer.testing import CliRunner

from pkgtool.cli import _register, app
from pkgtool.create.licenses import LICENSES
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
    (["pytest"], "Invalid package name `pytest`: it is the name of a Python module"),
    (["my_pkg", "--license", ""], "Invalid license"),
    (["my_pkg", "--node", "n1:teleporter"], "Unknown node kind `teleporter`"),
    (["my_pkg", "--build-type", "ament_cmake"], "ament_python packages only"),
    (["my_pkg", "other_pkg"], "Unexpected argument `other_pkg`"),
    (["--dependencies", "rclpy", "std_msgs", "my_pkg"], "every word after --dependencies is a "
                                                        "dependency"),
    (["my_pkg", "--msg", "std_msgs/msg/Int32"], "no such node takes it"),
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
    header = (out / "my_pkg" / "my_pkg" / "beat.py").read_text().splitlines()[:3]
    assert header == ["# Copyright 2000 Grace Hopper", "#",
                      "# Licensed under the Apache License, Version 2.0 (the \"License\");"]
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
    assert "every word up to the next option" in " ".join(result.output.split())
    assert "--package-format, --package_format N" in result.output


def test_dependencies_take_every_word_up_to_the_next_option(tmp_path: Path) -> None:
    """As `ros2 pkg create`: the name is the positional; stray words are usage errors."""
    result = _create(tmp_path, "my_pkg", *MAINTAINER, "--dependencies", "sensor_msgs",
                     "numpy", "--node", "beat:timer", "--dependencies", "geometry_msgs,std_msgs",
                     "--package_format", "2")
    assert result.exit_code == 0, result.output
    manifest = load_package(tmp_path / "my_pkg").manifest
    assert manifest.format == 2
    assert manifest.depends({"depend"}) == {"geometry_msgs", "rclpy", "sensor_msgs", "std_msgs"}
    assert "python3-numpy" in manifest.depends({"exec_depend"})


def test_license_question_mark_lists_what_ships(tmp_path: Path) -> None:
    result = _create(tmp_path, "my_pkg", "--license", "?")
    assert result.exit_code == 0 and list(tmp_path.iterdir()) == []
    assert all(spdx in result.output for spdx in LICENSES) and "BSD-2.0" in result.output


def test_a_license_without_text_is_written_with_a_warning(tmp_path: Path) -> None:
    result = _create(tmp_path, "my_pkg", *MAINTAINER, "--license", "Proprietary",
                     "--node", "beat:timer", "--copyright-year", "2026")
    assert result.exit_code == 0
    assert "warning: `Proprietary` is not an SPDX license expression" in result.output
    root = tmp_path / "my_pkg"
    assert not (root / "LICENSE").exists()
    assert [lic.value for lic in load_package(root).manifest.licenses] == ["Proprietary"]
    assert (root / "my_pkg" / "beat.py").read_text().startswith(
        "# Copyright 2026 Jane Doe\n# SPDX-License-Identifier: LicenseRef-Proprietary\n\n")


def test_a_package_inside_a_package_is_refused(tmp_path: Path) -> None:
    assert _create(tmp_path, "outer_pkg", *MAINTAINER).exit_code == 0
    inner = tmp_path / "outer_pkg" / "sub"
    result = CliRunner().invoke(app, ["create", "inner_pkg", *MAINTAINER,
                                      "--destination-directory", str(inner)])
    assert result.exit_code == 2
    assert "is inside the package `outer_pkg`" in result.output
    assert not inner.exists()
