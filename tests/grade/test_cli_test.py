"""`pkgtool test`: real colcon in a temporary workspace; siblings built; source trees untouched."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from pkgtool.grade.sources import tree_digest
from tests.helpers import MINIMAL_MANIFEST, run_cli, write_tree

pytestmark = [pytest.mark.ros, pytest.mark.colcon, pytest.mark.slow]

SETUP = """\
from setuptools import find_packages, setup

setup(
    name='{name}',
    version='0.1.0',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/{name}']),
        ('share/{name}', ['package.xml']),
    ],
    install_requires=['setuptools'],
    extras_require={{'test': ['pytest']}},
)
"""


def _package(root: Path, name: str, files: dict[str, str], depends: str = "") -> Path:
    manifest = MINIMAL_MANIFEST.format(name=name)
    if depends:
        manifest = manifest.replace("<exec_depend>rclpy", f"<depend>{depends}</depend>\n"
                                    "  <exec_depend>rclpy")
    return write_tree(root / name, {"package.xml": manifest, "setup.py": SETUP.format(name=name),
                                    f"resource/{name}": "", f"{name}/__init__.py": "", **files})


def test_a_package_is_built_with_its_sibling_and_tested(tmp_path: Path) -> None:
    src = tmp_path / "ws" / "src"
    _package(src, "greeter_lib", {"greeter_lib/words.py": "HELLO = 'hello'\n"})
    test = ("from greeter_lib.words import HELLO\n\n\n"
            "def test_hello():\n    assert HELLO == 'hello'\n")
    app = _package(src, "greeter_app", {"test/test_app.py": test}, depends="greeter_lib")
    before = tree_digest(tmp_path / "ws")
    result = run_cli("test", "ws/src/greeter_app", "--format", "json", cwd=tmp_path)
    assert result.exit_code == 0, result.output
    document = json.loads(result.stdout)
    assert document["ok"] and [p["name"] for p in document["packages"]] == ["greeter_app"]
    assert document["packages"][0]["counts"]["passed"] == 1
    assert document["packages"][0]["tests"][0]["name"].endswith("test_app.test_hello")
    assert tree_digest(tmp_path / "ws") == before
    assert not (app / "build").exists() and not (tmp_path / "ws" / "build").exists()


def test_failures_and_no_tests_fail_the_run(tmp_path: Path) -> None:
    src = tmp_path / "ws" / "src"
    _package(src, "good_pkg", {"test/test_ok.py": "def test_ok():\n    assert True\n"})
    _package(src, "empty_pkg", {})
    _package(src, "bad_pkg", {"test/test_bad.py": "def test_bad():\n    assert 1 == 2\n"})
    result = run_cli("test", "ws", "--format", "text", "--timeout", "300", cwd=tmp_path)
    assert result.exit_code == 1, result.output
    assert "good_pkg: ok: 1 passed" in result.stdout
    assert "empty_pkg: FAILED: no tests ran" in result.stdout
    assert "bad_pkg: FAILED: 1 failed" in result.stdout
    assert "FAILED  bad_pkg.test.test_bad.test_bad" in result.stdout
    assert "assert 1 == 2" in result.stdout


def test_usage_errors(tmp_path: Path) -> None:
    (tmp_path / "empty").mkdir()
    missing = run_cli("test", "nope", cwd=tmp_path)
    assert missing.exit_code == 2 and "is not a folder" in missing.output
    empty = run_cli("test", "empty", cwd=tmp_path)
    assert empty.exit_code == 2 and "No package" in empty.output
