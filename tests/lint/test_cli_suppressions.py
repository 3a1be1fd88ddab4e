"""Inline suppressions end to end: `# pkgtool: ignore[RULE]`, `<!-- pkgtool: ignore RULE -->`."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from pkgtool.commands import ExitCode
from tests.helpers import MINIMAL_MANIFEST, run_cli, write_tree


def _lint(root: Path, *args: str) -> list[tuple[str, str, int]]:
    result = run_cli("lint", "-f", "json", *args, cwd=root)
    assert result.exit_code in (ExitCode.OK, ExitCode.FINDINGS), result.output
    return [(f["rule"], f["path"], f["line"]) for f in json.loads(result.stdout)["findings"]]


@pytest.mark.parametrize(("comment", "silenced"), [
    ("# pkgtool: ignore[SYN001]", True),
    ("# pkgtool: ignore[unparsable-file]", True),
    ("# pkgtool: ignore[MAN001, SYN001]", True),
    ("# pkgtool: ignore", True),
    ("# pkgtool: ignore[ALL]", True),  # the word --select uses for every rule
    ("# pkgtool: ignore[SYN002]", False),
    ("# unrelated comment", False),
])
def test_python_comment_on_the_reported_line(tmp_path: Path, comment: str, silenced: bool) -> None:
    write_tree(tmp_path, {"package.xml": MINIMAL_MANIFEST.format(name="pkg"),
                          "pkg/node.py": f"x = 1\ndef talk(:  {comment}\n    pass\n"})
    expected = [] if silenced else [("SYN001", "pkg/node.py", 2)]
    assert _lint(tmp_path, "--select", "SYN") == expected


@pytest.mark.parametrize(("comment", "silenced"), [
    ("# noqa: F821", True),  # flake8's undefined name: the same check as PYC001
    ("# noqa: E501, F821", True),
    ("# noqa:F821 # pkgtool: ignore[DEP001]", True),
    ("# noqa: F401", False),
    ("# noqa", False),  # a bare noqa is flake8's business
])
def test_flake8_noqa_of_the_same_check(tmp_path: Path, comment: str, silenced: bool) -> None:
    write_tree(tmp_path, {"package.xml": MINIMAL_MANIFEST.format(name="pkg"),
                          "setup.py": "from setuptools import setup\n"
                                      "setup(name='pkg', packages=['pkg'])\n",
                          "pkg/__init__.py": "",
                          "pkg/node.py": f"def talk():\n    return injected  {comment}\n"})
    expected = [] if silenced else [("PYC001", "pkg/node.py", 2)]
    assert _lint(tmp_path, "--select", "PYC001") == expected


def test_suppression_on_another_line_does_not_apply(tmp_path: Path) -> None:
    write_tree(tmp_path, {"package.xml": MINIMAL_MANIFEST.format(name="pkg"),
                          "pkg/node.py": "# pkgtool: ignore[SYN001]\ndef talk(:\n    pass\n"})
    assert _lint(tmp_path, "--select", "SYN") == [("SYN001", "pkg/node.py", 2)]


def _manifest_with_bad_version(marker: str) -> str:
    return MINIMAL_MANIFEST.format(name="pkg").replace(
        "  <version>0.1.0</version>\n", f"{marker}  <version>1.0</version>\n")


def test_xml_comment_on_the_line_before_covers_the_next_line(tmp_path: Path) -> None:
    write_tree(tmp_path, {"package.xml": _manifest_with_bad_version("")})
    reported = _lint(tmp_path, "--select", "MAN002")
    assert [code for code, _, _ in reported] == ["MAN002"]
    write_tree(tmp_path, {"package.xml": _manifest_with_bad_version(
        "  <!-- pkgtool: ignore MAN002 -->\n")})
    assert _lint(tmp_path, "--select", "MAN002") == []


def test_xml_comment_at_the_end_of_the_line(tmp_path: Path) -> None:
    manifest = MINIMAL_MANIFEST.format(name="pkg").replace(
        "<version>0.1.0</version>",
        "<version>1.0</version> <!-- pkgtool: ignore invalid-version -->")
    write_tree(tmp_path, {"package.xml": manifest})
    assert _lint(tmp_path, "--select", "MAN002") == []


def test_xml_comment_for_another_rule_does_not_apply(tmp_path: Path) -> None:
    write_tree(tmp_path, {"package.xml": _manifest_with_bad_version(
        "  <!-- pkgtool: ignore MAN001 -->\n")})
    assert [code for code, _, _ in _lint(tmp_path, "--select", "MAN002")] == ["MAN002"]
