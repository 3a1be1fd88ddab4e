"""Rule selection, severities and strictness from the command line and ``[tool.pkgtool]``."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import Result

from pkgtool.commands import ExitCode
from tests.helpers import correct_package_files, run_cli, write_tree

BROKEN = "def talk(:\n    pass\n"


@pytest.fixture()
def workspace(tmp_path: Path) -> Path:
    """A correct package plus two modules with syntax errors (SYN001, nothing else)."""
    files = {f"src/pkg/{k}": v for k, v in correct_package_files("pkg").items()}
    files.update({"src/pkg/pkg/node.py": BROKEN, "src/pkg/test/test_node.py": BROKEN})
    return write_tree(tmp_path, files)


def _codes(result: Result) -> list[tuple[str, str, str]]:
    output = json.loads(result.stdout)
    return [(f["rule"], f["severity"], f["path"]) for f in output["findings"]]


@pytest.fixture()
def two_defects(workspace: Path) -> Path:
    """The workspace plus a binary module: one SYN001 per broken module and one SYN002."""
    (workspace / "src" / "pkg" / "pkg" / "blob.py").write_bytes(b"\x00\x01 binary")
    return workspace


@pytest.mark.parametrize(("args", "expected"), [
    (["--select", "SYN002"], {"SYN002"}),
    (["--ignore", "SYN001"], {"SYN002"}),
    (["--ignore", "unparsable-file"], {"SYN002"}),
    (["--select", "SYN", "--ignore", "SYN001"], {"SYN002"}),
    (["--select", "SYN00", "--ignore", "unparsable-file"], {"SYN002"}),
    (["--select", "unparsable-file"], {"SYN001"}),
    ([], {"SYN001", "SYN002"}),
    (["--select", "SYN", "--ignore", "SYN0"], set()),
])
def test_select_and_ignore_by_code_family_prefix_and_name(two_defects: Path, args: list[str],
                                                          expected: set[str]) -> None:
    result = run_cli("lint", "-f", "json", *args, cwd=two_defects)
    assert {code for code, _, _ in _codes(result)} == expected
    assert result.exit_code == (ExitCode.FINDINGS if expected else ExitCode.OK)


def test_extend_select_adds_to_the_selection(workspace: Path) -> None:
    result = run_cli("lint", "-f", "json", "--select", "SYN002", "--extend-select", "SYN001",
                     cwd=workspace)
    assert result.exit_code == ExitCode.FINDINGS
    assert {code for code, _, _ in _codes(result)} == {"SYN001"}


def test_unknown_selector_on_the_command_line_is_a_usage_error(workspace: Path) -> None:
    result = run_cli("lint", "--select", "SYN001,XYZ123", cwd=workspace)
    assert result.exit_code == ExitCode.USAGE
    assert "Unknown rule selector `XYZ123` in the command line" in result.stderr


def _configure(root: Path, text: str) -> None:
    (root / "pyproject.toml").write_text(text)


def test_severity_override_strict_and_no_strict(workspace: Path) -> None:
    _configure(workspace, '[tool.pkgtool]\nselect = ["SYN"]\n'
               '[tool.pkgtool.severity]\nSYN001 = "warning"\n')
    relaxed = run_cli("lint", "-f", "json", cwd=workspace)
    assert relaxed.exit_code == ExitCode.OK
    assert {s for _, s, _ in _codes(relaxed)} == {"warning"}
    assert run_cli("lint", "--strict", cwd=workspace).exit_code == ExitCode.FINDINGS
    _configure(workspace / "src" / "pkg", "[tool.pkgtool]\nstrict = true\n")
    assert run_cli("lint", cwd=workspace).exit_code == ExitCode.FINDINGS
    assert run_cli("lint", "--no-strict", cwd=workspace).exit_code == ExitCode.OK


def test_info_findings_never_fail_and_quiet_hides_them(workspace: Path) -> None:
    _configure(workspace, '[tool.pkgtool]\nselect = ["SYN"]\n'
               '[tool.pkgtool.severity]\nunparsable-file = "info"\n')
    shown = run_cli("lint", "--strict", "-f", "json", cwd=workspace)
    assert shown.exit_code == ExitCode.OK and len(_codes(shown)) == 2
    hidden = run_cli("lint", "--quiet", "-f", "json", cwd=workspace)
    assert _codes(hidden) == [] and json.loads(hidden.stdout)["summary"]["info"] == 0


def test_per_file_ignores_in_the_package_config(workspace: Path) -> None:
    _configure(workspace / "src" / "pkg",
               '[tool.pkgtool]\nselect = ["SYN"]\n[tool.pkgtool.per-file-ignores]\n'
               '"test/*" = ["unparsable-file"]\n')
    result = run_cli("lint", "-f", "json", cwd=workspace)
    assert _codes(result) == [("SYN001", "error", "src/pkg/pkg/node.py")]


def test_command_line_overrides_the_configuration(workspace: Path) -> None:
    _configure(workspace, '[tool.pkgtool]\nignore = ["SYN"]\n')
    assert run_cli("lint", cwd=workspace).exit_code == ExitCode.OK
    assert run_cli("lint", "--select", "SYN001", cwd=workspace).exit_code == ExitCode.FINDINGS
    assert run_cli("lint", "--isolated", "--select", "SYN",
                   cwd=workspace).exit_code == ExitCode.FINDINGS


@pytest.mark.parametrize(("text", "named"), [
    ("[tool.pkgtool]\nselekt = []\n", "Unknown key `selekt`"),
    ("[tool.pkgtool]\nignore = [\"MAN999\"]\n", "Unknown rule selector `MAN999`"),
    ("[tool.pkgtool.severity]\nSYN001 = \"fatal\"\n", "`SYN001`"),
    ("[tool.pkgtool\n", "is not valid TOML"),
])
def test_bad_configuration_is_a_usage_error_naming_the_key(workspace: Path, text: str,
                                                           named: str) -> None:
    _configure(workspace / "src" / "pkg", text)
    result = run_cli("lint", cwd=workspace)
    assert result.exit_code == ExitCode.USAGE
    assert named in result.stderr and "pyproject.toml" in result.stderr
