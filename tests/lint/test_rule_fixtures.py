"""Every rule has a failing and a passing fixture, and reports exactly what the markers say.

Fixtures live in ``tests/fixtures/<CODE>/{good,bad}/<case>/`` as minimal package trees.
In ``bad`` cases each expected finding is marked on its line: ``# expect: CODE`` (Python,
setup.cfg, YAML) or ``<!-- expect: CODE -->`` (XML). Findings with no line of their own (a
missing file) are listed in an ``EXPECT`` file of the case as ``path:line CODE`` lines.
``good`` cases must give no finding of that code. A case that is not a package but a colcon
workspace (``<case>/src/<package>/...``) is linted package by package with its workspace, as
``pkgtool lint`` does; its paths are then relative to the case. So is a case holding several
workspaces (``<case>/<ws>/src/<package>/...``), linted in one run. A case may name the target
distribution in a ``ROSDISTRO`` file, and list in a ``GROW`` file (one path a line) files the
test pads with blank lines past pkgtool's read limit, so no multi-megabyte file is committed.
A ``bad`` case whose findings depend on an older Python running pkgtool names the version
that reads its files in a ``PYTHON_BELOW`` file (``3.12``): from that version on it must
report nothing.
"""

from __future__ import annotations

import re
import shutil
import sys
from pathlib import Path

import pytest

from pkgtool.findings import Finding
from pkgtool.model.context import Context, context_for, workspace_index
from pkgtool.model.files import MAX_FILE_BYTES
from pkgtool.model.package import load_package
from pkgtool.workspace import discover, is_package
from pkgtool.rules.registry import load_all
from tests.helpers import findings

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"
MARKER = re.compile(r"expect:\s*([A-Z]{3}\d{3}(?:\s*,\s*[A-Z]{3}\d{3})*)")


def _cases(kind: str) -> list[tuple[str, Path]]:
    return [(code_dir.name, case) for code_dir in sorted(FIXTURES.iterdir()) if code_dir.is_dir()
            for case in sorted((code_dir / kind).glob("*")) if case.is_dir()]


def _expected(case: Path, code: str) -> set[tuple[str, int]]:
    expected: set[tuple[str, int]] = set()
    for file in case.rglob("*"):
        if not file.is_file() or file.name == "EXPECT":
            continue
        try:
            lines = file.read_text(encoding="utf-8").splitlines()
        except (UnicodeDecodeError, OSError):
            continue
        for number, line in enumerate(lines, 1):
            match = MARKER.search(line)
            if match and code in re.split(r"\s*,\s*", match.group(1)):
                expected.add((file.relative_to(case).as_posix(), number))
    listing = case / "EXPECT"
    if listing.is_file():
        for line in listing.read_text().splitlines():
            if line.strip() and line.split()[-1] == code:
                path, _, number = line.split()[0].rpartition(":")
                expected.add((path, int(number)))
    return expected


def _grown(case: Path, into: Path) -> Path:
    """``case``, or its copy in ``into`` with the files its ``GROW`` file lists made larger
    than pkgtool reads."""
    listing = case / "GROW"
    if not listing.is_file():
        return case
    copy = into / case.name
    shutil.copytree(case, copy)
    for name in listing.read_text().split():
        with (copy / name).open("ab") as file:
            file.write(b"\n" * (MAX_FILE_BYTES + 1))
    return copy


def _findings(case: Path, code: str) -> list[tuple[str, Finding]]:
    """(package folder relative to the case, finding) for every finding of ``code``."""
    marker = case / "ROSDISTRO"
    distro = marker.read_text().strip() if marker.is_file() else Context().distro
    sources = [] if is_package(case) else ["."] if (case / "COLCON_ROOT").is_file() else [
        str(src.relative_to(case)) for src in [case / "src", *sorted(case.glob("*/src"))]
        if src.is_dir()]  # COLCON_ROOT: colcon runs in the case folder, src/ and all
    is_workspace = bool(sources)
    roots = list(discover(sources, cwd=case).packages) if is_workspace else [case]
    index = workspace_index(roots) if is_workspace else {}
    return [("" if root == case else root.relative_to(case).as_posix() + "/", finding)
            for root in roots for finding in
            findings(load_package(root, context_for(root, index, distro)), code)]


@pytest.mark.parametrize(("code", "case"), _cases("bad"), ids=lambda v: getattr(v, "name", v))
def test_bad_fixture_reports_exactly_the_marked_lines(code: str, case: Path,
                                                      tmp_path: Path) -> None:
    got = {(prefix + f.span.path, f.span.line)
           for prefix, f in _findings(_grown(case, tmp_path), code)}
    expected = _expected(case, code)
    assert expected, f"{case} marks no expected {code} finding"
    assert got == (set() if _reads_its_syntax(case) else expected)


def _reads_its_syntax(case: Path) -> bool:
    """True when the case's ``PYTHON_BELOW`` version is not above the running Python's."""
    marker = case / "PYTHON_BELOW"
    if not marker.is_file():
        return False
    major, minor = marker.read_text().strip().split(".")
    return sys.version_info[:2] >= (int(major), int(minor))


@pytest.mark.parametrize(("code", "case"), _cases("good"), ids=lambda v: getattr(v, "name", v))
def test_good_fixture_reports_nothing(code: str, case: Path, tmp_path: Path) -> None:
    assert _findings(_grown(case, tmp_path), code) == []


def test_every_rule_has_good_and_bad_fixtures() -> None:
    missing = [code for code in load_all()
               if not list((FIXTURES / code / "good").glob("*")) or
               not list((FIXTURES / code / "bad").glob("*"))]
    assert missing == []
