"""The IFC rules agree with rosidl itself: what they report, rosidl refuses, and the interface
files of every installed Jazzy interface package give them nothing to report.

rosidl_adapter (installed with the ROS wheels) parses ``.msg``, ``.srv`` and ``.action``
files for ``rosidl_generate_interfaces``; the test then refuses a field
whose message type is not among those known (here: every message the wheels install, and
the fixture package's own), as ``rosidl_generate_interfaces`` does.
"""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from rosidl_adapter import parser as rosidl

from pkgtool.model.cmake_interfaces import listed_interfaces
from pkgtool.model.package import load_package
from tests.helpers import findings
from tests.lint.test_rule_fixtures import FIXTURES, MARKER

pytestmark = pytest.mark.oracle

SHARE = Path(sys.prefix) / "share"
CODES = ("IFC001", "IFC002", "IFC003")
_PARSERS = {"msg": rosidl.parse_message_string, "srv": rosidl.parse_service_string,
            "action": rosidl.parse_action_string}


def _installed_messages() -> set[rosidl.BaseType]:
    return {rosidl.BaseType(f"{path.parts[-3]}/{path.stem}")
            for path in SHARE.glob("*/msg/*.msg")}


def _rosidl_refuses(package: str, kind: str, name: str, text: str, known: set) -> bool:
    """True when rosidl cannot parse ``text`` or finds a field of unknown type in it."""
    try:
        spec = _PARSERS[kind](package, name, text)
    except Exception:  # rosidl raises many kinds (NameError, IndexError, InvalidValue...)
        return True
    return any(not field.type.is_primitive_type() and
               (field.type.pkg_name == package or (SHARE / field.type.pkg_name).is_dir()) and
               rosidl.BaseType(rosidl.BaseType.__str__(field.type)) not in known
               for field in _fields(spec))  # types of packages not installed: unknown


def _fields(spec: object) -> list:
    """The fields of a parsed message, service or action (rosidl's ``validate_field_types``
    does this, but not for actions in this rosidl)."""
    parts = [getattr(spec, part) for part in ("request", "response", "goal", "result",
                                              "feedback") if hasattr(spec, part)]
    return [field for part in parts or [spec] for field in part.fields]


def _interface_files(case: Path) -> list[Path]:
    return sorted(path for kind in _PARSERS for path in case.glob(f"{kind}/**/*.{kind}"))


def _known(case: Path, package: str) -> set[rosidl.BaseType]:
    own = {rosidl.BaseType(f"{package}/{path.stem}") for path in case.glob("msg/**/*.msg")
           if rosidl.is_valid_message_name(path.stem)}
    return _installed_messages() | own


def _cases(kind: str) -> list[Path]:
    """The fixture packages of ``kind`` that rosidl would build (ROS 2, CMake)."""
    return [case for code in CODES for case in sorted((FIXTURES / code / kind).glob("*"))
            if (case / "CMakeLists.txt").is_file() and "catkin" not in
            (case / "package.xml").read_text()]


@pytest.mark.parametrize("case", _cases("good"), ids=lambda case: case.name)
def test_rosidl_accepts_every_good_fixture(case: Path) -> None:
    package = load_package(case).name
    known = _known(case, package)
    listed = listed_interfaces((case / "CMakeLists.txt").read_text(),
                               [p.relative_to(case).as_posix() for p in case.rglob("*")]).files
    refused = [path.name for path in _interface_files(case)
               if path.relative_to(case).as_posix() in listed and _rosidl_refuses(
                   package, path.parts[len(case.parts)], path.stem, path.read_text(), known)]
    assert refused == []


@pytest.mark.parametrize("case", _cases("bad"), ids=lambda case: case.name)
def test_rosidl_refuses_every_marked_line_and_file(case: Path) -> None:
    package = load_package(case).name
    known = _known(case, package)
    listed = (case / "EXPECT").read_text() if (case / "EXPECT").is_file() else ""
    accepted = []
    for path in _interface_files(case):
        kind = path.parts[len(case.parts)]
        text = path.read_text()
        marked_file = MARKER.search(text) or path.relative_to(case).as_posix() in listed
        if marked_file and not _rosidl_refuses(package, kind, path.stem, text, known):
            accepted.append(path.name)
        lines = text.splitlines()
        for number, line in enumerate(lines, 1):
            before = [each for each in lines[:number - 1] if not MARKER.search(each)]
            if MARKER.search(line) and kind == "msg" and number > 1 and not _rosidl_refuses(
                    package, kind, path.stem, "\n".join([*before, line]), known):
                accepted.append(f"{path.name}:{number}")
    assert accepted == []


def test_installed_interface_packages_give_no_finding(tmp_path: Path) -> None:
    """Every interface package the ROS wheels install (their share folders hold package.xml
    and the interface files), rebuilt as a source package whose CMakeLists.txt globs its
    interface files, is read without an IFC finding."""
    shares = sorted({path.parents[1] for path in SHARE.glob("*/*/*.*")
                     if path.parent.name in _PARSERS and (path.parents[1] / "package.xml")
                     .is_file()})
    assert len(shares) > 20
    reported = []
    for share in shares:
        root = tmp_path / share.name
        for path in [share / "package.xml", *_interface_files(share)]:
            copy = root / path.relative_to(share)
            copy.parent.mkdir(parents=True, exist_ok=True)
            copy.write_bytes(path.read_bytes())
        (root / "CMakeLists.txt").write_text(
            'file(GLOB_RECURSE FILES RELATIVE "${CMAKE_CURRENT_SOURCE_DIR}" "msg/*.msg" '
            '"srv/*.srv" "action/*.action")\nrosidl_generate_interfaces(${PROJECT_NAME} '
            '${FILES})\n')
        reported += [f"{share.name}: {finding.span.path}:{finding.span.line} {finding.message}"
                     for code in CODES for finding in findings(load_package(root), code)]
    assert reported == []
