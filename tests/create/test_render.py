"""Generated packages: the right files, lint-clean under every rule, deterministic to the byte."""

from __future__ import annotations

import ast
import subprocess
import sys
from pathlib import Path

import pytest

from pkgtool.create.headers import header
from pkgtool.create.licenses import LICENSES, license_text
from pkgtool.model.package import load_package
from tests.create.conftest import ALL_KINDS, OTHER_TYPES
from tests.helpers import findings


def _files(root: Path) -> dict[str, bytes]:
    return {p.relative_to(root).as_posix(): p.read_bytes() for p in sorted(root.rglob("*"))
            if p.is_file()}


@pytest.mark.parametrize("package_format", [3, 2])
@pytest.mark.parametrize("license_id", LICENSES)
def test_every_license_and_format_gives_a_lint_clean_package(create, license_id: str,
                                                             package_format: int) -> None:
    result = create(license=license_id, package_format=package_format, nodes=ALL_KINDS,
                    launch=True, config=True, library_name="util")
    assert not result.error
    package = load_package(result.root)
    assert findings(package) == []
    assert package.manifest.format == package_format
    assert package.manifest.has_schema_line
    assert [lic.value for lic in package.manifest.licenses] == [license_id]
    assert (result.root / "LICENSE").read_text() == license_text(license_id, year=2026,
                                                                 holder="Jane Doe")


@pytest.mark.parametrize("nodes", [(), ("only:timer",), OTHER_TYPES,
                                   *[(spec,) for spec in ALL_KINDS]])
def test_each_node_kind_and_interface_gives_a_lint_clean_package(create, nodes) -> None:
    result = create(nodes=nodes)
    assert not result.error
    assert findings(load_package(result.root)) == []


def test_the_package_has_what_ros2_pkg_create_writes_and_more(create) -> None:
    result = create(nodes=ALL_KINDS, launch=True, config=True, library_name="util")
    files = _files(result.root)
    name = "demo_pkg"
    expected = {"package.xml", "setup.py", "setup.cfg", "LICENSE", f"resource/{name}",
                f"{name}/__init__.py", f"{name}/util/__init__.py", "test/conftest.py",
                "test/test_copyright.py", "test/test_flake8.py", "test/test_pep257.py",
                f"launch/{name}.launch.py", "config/params.yaml"}
    expected |= {f"{name}/{spec.split(':')[0]}.py" for spec in ALL_KINDS}
    expected |= {f"test/test_{spec.split(':')[0]}.py" for spec in ALL_KINDS}
    assert set(files) == expected
    assert files[f"resource/{name}"] == b""
    setup_py = files["setup.py"].decode()
    assert "extras_require={'test': ['pytest']}" in setup_py and "tests_require" not in setup_py
    assert "find_packages(exclude=['test'])" in setup_py
    assert files["setup.cfg"].decode() == (f"[develop]\nscript_dir=$base/lib/{name}\n"
                                           f"[install]\ninstall_scripts=$base/lib/{name}\n")
    for linter in ("flake8", "pep257", "copyright"):
        assert f"from ament_{linter}.main import" in files[f"test/test_{linter}.py"].decode()
    head = header(year=2026, holder="Jane Doe", license_="Apache-2.0", expression="Apache-2.0")
    for path, data in files.items():
        if path.endswith(".py"):
            text = data.decode()
            assert text.startswith(head + "\n"), path
            ast.parse(text, path)


@pytest.mark.parametrize("launch", [True, False])
def test_the_parameters_file_says_how_its_values_reach_the_nodes(create, launch: bool) -> None:
    result = create(nodes=("talker:publisher",), config=True, launch=launch)
    comment = (result.root / "config" / "params.yaml").read_text().split("\ntalker:")[0]
    assert ("launch/demo_pkg.launch.py" in comment) == launch
    params_file = "--params-file install/demo_pkg/share/demo_pkg/config/params.yaml"
    assert (params_file in comment) != launch


def test_a_license_ament_copyright_does_not_know_is_checked_by_pkgtool_alone(create) -> None:
    result = create(license="GPL-2.0-or-later", nodes=("beat:timer",))
    copyright_test = (result.root / "test" / "test_copyright.py").read_text()
    assert "from ament_copyright" not in copyright_test
    assert "pytest.importorskip('pkgtool.style.api'" in copyright_test
    assert not (result.root / "LICENSE").exists()
    assert findings(load_package(result.root)) == []


def test_output_is_deterministic_byte_for_byte(create, tmp_path: Path) -> None:
    options = {"nodes": ALL_KINDS, "launch": True, "config": True, "library_name": "util",
               "dependencies": ("numpy", "sensor_msgs"), "license": "BSD-3-Clause"}
    first = create(destination=tmp_path / "a", **options)
    second = create(destination=tmp_path / "b", **options)
    assert _files(first.root) == _files(second.root)
    assert first.tree == second.tree


def test_unusual_text_is_escaped_and_wrapped(create) -> None:
    description = 'Uses <xml> & "quotes", it\'s long: ' + "é" * 120
    result = create("a" * 40, maintainer_name="Zoë O'Brien-Łukasz", description=description,
                    nodes=("n" * 32 + ":action-client", "m" * 32 + ":client"), launch=True,
                    config=True)
    assert not result.error
    package = load_package(result.root)
    assert package.manifest.description.value == description
    assert package.manifest.maintainers[0].name == "Zoë O'Brien-Łukasz"
    assert findings(package) == []


def test_an_unused_declared_dependency_is_only_an_info_hint(create) -> None:
    result = create(dependencies=("numpy",))
    assert [(f.code, f.severity.value) for f in findings(load_package(result.root))] == [
        ("DEP006", "info")]


def test_pkgtool_lint_strict_reports_nothing(create) -> None:
    result = create(nodes=ALL_KINDS, launch=True, config=True, library_name="util")
    done = subprocess.run([sys.executable, "-m", "pkgtool", "lint", "--strict", str(result.root)],
                          capture_output=True, text=True, timeout=120, check=False)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "No findings" in done.stdout
