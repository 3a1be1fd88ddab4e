"""The MAN rules say precisely what is wrong and suggest the right value."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.helpers import findings, make_package
from tests.lint.test_manifest_xsd_oracle import EXPORT, doc, head


def _one(tmp_path: Path, code: str, xml: str, **files: str) -> tuple[str, str | None]:
    package = make_package(tmp_path / "demo_pkg", {"package.xml": xml, **files})
    found = findings(package, code)
    assert len(found) == 1, found
    return found[0].message, found[0].fix


@pytest.mark.parametrize(("name", "message", "fix"), [
    ("My-Robot", "Package name `My-Robot` has uppercase letters", "`my_robot`"),
    ("robot__arm_", "Package name `robot__arm_` has a double underscore", "`robot_arm`"),
    ("2d_mapper", "Package name `2d_mapper` does not start with a letter", None),
    ("demo.pkg", "Package name `demo.pkg` contains `.`", "`demo_pkg`"),
])
def test_package_name(tmp_path: Path, name: str, message: str, fix: str | None) -> None:
    got, hint = _one(tmp_path, "MAN001", doc(head=head(name=f"<name>{name}</name>")))
    assert got == message
    assert hint is not None
    assert (fix in hint) if fix else not hint.startswith("Rename")


@pytest.mark.parametrize(("version", "message", "fix"), [
    ("1.0", "Package version `1.0` is not three numbers `X.Y.Z`", "Write `1.0.0`"),
    ("01.2.3", "Package version `01.2.3` has a leading zero", "Write `1.2.3`"),
    ("v2.0.1", "Package version `v2.0.1` is not three numbers `X.Y.Z`", "Write `2.0.1`"),
    ("1.0.0-rc1", "Package version `1.0.0-rc1` is not three numbers `X.Y.Z`", None),
])
def test_version(tmp_path: Path, version: str, message: str, fix: str | None) -> None:
    got, hint = _one(tmp_path, "MAN002", doc(head=head(version=f"<version>{version}</version>")))
    assert (got, hint if fix else None) == (message, fix)


def test_missing_format_attribute_explains_format_1(tmp_path: Path) -> None:
    message, fix = _one(tmp_path, "MAN006", doc("<exec_depend>rclpy</exec_depend>", fmt=None))
    assert message == ("`<exec_depend>` needs format 2 or 3, but `<package>` has no `format` "
                       "attribute, which means format 1")
    assert fix == 'Add `format="3"` to `<package>`'


def test_misspelt_tag_gets_the_intended_one(tmp_path: Path) -> None:
    message, fix = _one(tmp_path, "MAN005", doc("<exec_depends>rclpy</exec_depends>"))
    assert (message, fix) == ("Unknown element `<exec_depends>` in `<package>`",
                              "Rename it to `<exec_depend>`")


def test_out_of_order_names_the_element_to_pass(tmp_path: Path) -> None:
    message, _ = _one(tmp_path, "MAN004", doc("<exec_depend>rclpy</exec_depend>\n"
                                              "  <url>https://example.com</url>"))
    assert message == "`<url>` must come before `<exec_depend>` (line 9)"


@pytest.mark.parametrize(("body", "fix"), [
    ('<url type="source">https://github.com/a/b</url>', 'Write `type="repository"`'),
    ('<url type="issues">https://github.com/a/b/issues</url>', 'Write `type="bugtracker"`'),
    ('<url type="webside">https://example.com</url>', 'Write `type="website"`'),
    ("<url>git@github.com:ada/demo.git</url>",
     "Write `https://github.com/ada/demo.git` or `ssh://git@github.com/ada/demo.git`"),
])
def test_url_suggestions(tmp_path: Path, body: str, fix: str) -> None:
    assert _one(tmp_path, "MAN008", doc(body))[1] == fix


@pytest.mark.parametrize(("body", "message"), [
    ('<depend version_ge="1.0">a</depend>', "`<depend>` has no attribute `version_ge`"),
    ('<depend version_gte="1.0-1">a</depend>',
     '`version_gte="1.0-1"` is not a version (`X`, `X.Y` or `X.Y.Z`)'),
    ('<depend condition="$A == 1.5">a</depend>',
     "Condition `$A == 1.5` has characters a condition cannot contain"),
])
def test_attribute_messages(tmp_path: Path, body: str, message: str) -> None:
    assert _one(tmp_path, "MAN009", doc(body))[0] == message


def test_attribute_of_format_3_in_format_2(tmp_path: Path) -> None:
    message, fix = _one(tmp_path, "MAN009", doc('<depend condition="$X == 1">a</depend>',
                                                fmt="2"))
    assert (message, fix) == ("`condition` on `<depend>` needs format 3, not format 2",
                              'Set `format="3"` on `<package>`')


@pytest.mark.parametrize(("value", "fix"), [("4", None), (" 3", 'Write `format="3"`'),
                                            ("02", 'Write `format="2"`')])
def test_format(tmp_path: Path, value: str, fix: str | None) -> None:
    message, hint = _one(tmp_path, "MAN010", doc(fmt=value))
    assert message == f'`format="{value}"` is not a package.xml format (1, 2 or 3)'
    assert (hint if fix else None) == fix


@pytest.mark.parametrize(("body", "message", "fix"), [
    ("<exec_depend>python-opencv</exec_depend>",
     "`python-opencv` is a ROS 1 (Python 2) key that rosdep cannot resolve on ROS 2's Ubuntu "
     "releases", "Write `<exec_depend>python3-opencv</exec_depend>`"),
    ("<depend>opencv-python</depend>",
     "`opencv-python` is not a rosdep key (the key is `python3-opencv`)",
     "Write `<depend>python3-opencv</depend>`"),
    ("<buildtool_depend>ament_python</buildtool_depend>",
     "`ament_python` is a build type, not a package",
     "Remove this `<buildtool_depend>` and declare `<build_type>ament_python</build_type>` in "
     "`<export>`"),
])
def test_rosdep_key_suggestions(tmp_path: Path, body: str, message: str, fix: str) -> None:
    assert _one(tmp_path, "MAN018", doc(body + "\n  " + EXPORT)) == (message, fix)


def test_redundant_depend_names_both_lines(tmp_path: Path) -> None:
    message, fix = _one(tmp_path, "MAN012", doc("<depend>rclpy</depend>\n"
                                                "  <exec_depend>rclpy</exec_depend>"))
    assert message == ("`<exec_depend>rclpy</exec_depend>` is redundant with "
                       "`<depend>rclpy</depend>` (line 9)")
    assert fix == "Remove this `<exec_depend>`: `<depend>` already covers it"


def test_build_type_split_with_set001(tmp_path: Path) -> None:
    """ament_python without setup.py is SET001's; MAN015/MAN016 stay silent on it."""
    cmake_only = make_package(tmp_path / "a", {"package.xml": doc(),
                                               "CMakeLists.txt": "project(a)\n"})
    neither = make_package(tmp_path / "b", {"package.xml": doc()})
    assert findings(cmake_only, "MAN015", "MAN016") == []
    assert findings(neither, "MAN015", "MAN016") == []


def test_missing_build_type_in_setup_py_package(tmp_path: Path) -> None:
    message, _ = _one(tmp_path, "MAN015", doc("<exec_depend>rclpy</exec_depend>"),
                      **{"setup.py": "from setuptools import setup\nsetup()\n"})
    assert message == ("No `<build_type>` in `<export>`: colcon would build a Python package "
                       "with CMake, as `catkin`, and fail")


def test_non_manifest_problems_say_nothing(tmp_path: Path) -> None:
    broken = make_package(tmp_path / "a", {"package.xml": "<package format='3'><name>x</nam>"})
    unknown_format = make_package(tmp_path / "b", {"package.xml": doc(
        "<run_depend>x</run_depend><bogus/>", fmt="9")})
    man = [f"MAN{n:03d}" for n in range(1, 20)]
    assert findings(broken, *man) == []
    assert [f.code for f in findings(unknown_format, *man)] == ["MAN010"]
