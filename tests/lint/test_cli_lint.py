"""``pkgtool lint`` end to end (in-process CliRunner): paths, formats, output, exit codes."""

from __future__ import annotations

import json
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

from pkgtool.commands import ExitCode
from pkgtool.findings import Severity
from pkgtool.rules import registry
from pkgtool.rules.registry import _RULES, Rule, RuleInfo, load_all
from tests.helpers import MINIMAL_MANIFEST, run_cli, write_tree

BROKEN = "def talk(:\n    pass\n"


def _package(root: Path, name: str, module: str = "VALUE = 1\n") -> Path:
    return write_tree(root / name, {"package.xml": MINIMAL_MANIFEST.format(name=name),
                                    f"{name}/__init__.py": "", f"{name}/node.py": module})


@pytest.fixture()
def workspace(tmp_path: Path) -> Path:
    _package(tmp_path / "src", "good_pkg")
    _package(tmp_path / "src", "bad_pkg", BROKEN)
    return tmp_path


def test_clean_package_exits_zero(workspace: Path) -> None:
    result = run_cli("lint", "--select", "SYN", "src/good_pkg", cwd=workspace)
    assert result.exit_code == ExitCode.OK, result.output
    assert result.stdout == "No findings in 1 package.\n"


def test_error_finding_exits_one_with_location_code_and_help(workspace: Path) -> None:
    result = run_cli("lint", "--select", "SYN", cwd=workspace)
    assert result.exit_code == ExitCode.FINDINGS
    lines = result.stdout.splitlines()
    assert lines[0].startswith("src/bad_pkg/bad_pkg/node.py:1:")
    assert " SYN001 Python syntax error: " in lines[0]
    assert lines[1] == "  help: Fix the syntax at the reported line and column"
    assert lines[-1] == "Found 1 error, 0 warnings, 0 info in 1 of 2 packages."


def test_paths_are_relative_to_the_current_folder(workspace: Path) -> None:
    result = run_cli("lint", "--select", "SYN", "-f", "json", ".",
                     cwd=workspace / "src" / "bad_pkg")
    assert [f["path"] for f in json.loads(result.stdout)["findings"]] == ["bad_pkg/node.py"]


def test_missing_path_is_a_usage_error(workspace: Path) -> None:
    result = run_cli("lint", "src/good_pkg", "src/nope", cwd=workspace)
    assert result.exit_code == ExitCode.USAGE
    assert "Path `src/nope` does not exist" in result.stderr
    assert result.stdout == ""


def test_folder_without_packages_notes_it_and_passes(tmp_path: Path) -> None:
    (tmp_path / "docs").mkdir()
    result = run_cli("lint", "docs", cwd=tmp_path)
    assert result.exit_code == ExitCode.OK
    assert "No package (a folder with package.xml or setup.py) found under `docs`" in result.stderr


@pytest.mark.parametrize("fmt", ["text", "json", "sarif", "github", "junit"])
def test_every_format_reports_the_finding(workspace: Path, fmt: str) -> None:
    result = run_cli("lint", "--select", "SYN", "--format", fmt, cwd=workspace)
    assert result.exit_code == ExitCode.FINDINGS
    assert "src/bad_pkg/bad_pkg/node.py" in result.stdout
    assert "SYN001" in result.stdout


def test_output_file_receives_the_report(workspace: Path) -> None:
    result = run_cli("lint", "--select", "SYN", "-f", "json", "-o", "report.json", cwd=workspace)
    assert result.exit_code == ExitCode.FINDINGS and result.stdout == ""
    assert json.loads((workspace / "report.json").read_text())["summary"]["error"] == 1


def test_unwritable_output_is_a_usage_error(workspace: Path) -> None:
    result = run_cli("lint", "-o", "no/such/dir/report.txt", cwd=workspace)
    assert result.exit_code == ExitCode.USAGE
    assert "Cannot write `no/such/dir/report.txt`" in result.stderr


def test_exit_zero_masks_findings_only(workspace: Path) -> None:
    result = run_cli("lint", "--select", "SYN", "--exit-zero", cwd=workspace)
    assert result.exit_code == ExitCode.OK and "SYN001" in result.stdout


def test_explain_prints_the_rule_documentation(tmp_path: Path) -> None:
    result = run_cli("lint", "--explain", "unparsable-file", cwd=tmp_path)
    assert result.exit_code == ExitCode.OK
    assert result.stdout.startswith("# SYN001 unparsable-file\n")
    for section in ("## What it does", "## Why is this bad?", "## Example", "## Use instead"):
        assert section in result.stdout


def test_explain_unknown_rule_is_a_usage_error(tmp_path: Path) -> None:
    result = run_cli("lint", "--explain", "NOPE001", cwd=tmp_path)
    assert result.exit_code == ExitCode.USAGE and "Unknown rule `NOPE001`" in result.stderr


def test_list_rules_shows_every_rule(tmp_path: Path) -> None:
    table = run_cli("lint", "--list-rules", cwd=tmp_path)
    assert table.exit_code == ExitCode.OK
    assert table.stdout.splitlines()[0].split() == ["CODE", "NAME", "SEVERITY", "FIX", "SUMMARY"]
    listed = json.loads(run_cli("lint", "--list-rules", "-f", "json", cwd=tmp_path).stdout)
    assert [row["code"] for row in listed] == list(load_all())
    for code in load_all():
        assert code in table.stdout


@pytest.fixture()
def crashing_rule() -> Iterator[str]:
    def explode(package: object) -> Iterator[object]:
        """Explodes."""
        raise RuntimeError("boom")
        yield  # pragma: no cover

    load_all()
    _RULES["SYN999"] = Rule("SYN999", "test-explosion", Severity.WARNING, "Do nothing",
                            explode)
    registry.index()["SYN999"] = RuleInfo("SYN999", "test-explosion", Severity.WARNING, True,
                                          "none")
    yield "SYN999"
    del _RULES["SYN999"], registry.index()["SYN999"]


def test_a_crashing_rule_becomes_an_internal_error_finding(workspace: Path,
                                                           crashing_rule: str) -> None:
    result = run_cli("lint", "--select", f"SYN001,{crashing_rule}", "--exit-zero", "-f", "json",
                     cwd=workspace)
    assert result.exit_code == ExitCode.INTERNAL
    findings = json.loads(result.stdout)["findings"]
    crashes = [f for f in findings if f["rule"] == crashing_rule]
    assert len(crashes) == 2 and all(f["severity"] == "error" for f in crashes)
    assert "Internal error in rule `SYN999` (`test-explosion`): RuntimeError: boom" in \
        crashes[0]["message"]
    assert any(f["rule"] == "SYN001" for f in findings), "the other rules still ran"


def test_a_crash_while_reading_a_package_exits_three(workspace: Path,
                                                     monkeypatch: pytest.MonkeyPatch) -> None:
    def broken_reader(root: Path, context: object = None) -> None:
        raise ValueError("cannot model this")

    monkeypatch.setattr("pkgtool.model.package.load_package", broken_reader)
    result = run_cli("lint", "src/good_pkg", cwd=workspace)
    assert result.exit_code == ExitCode.INTERNAL
    assert "Internal error while reading the package at `src/good_pkg`: ValueError" in \
        result.stderr


def test_any_other_bug_exits_three_with_details(workspace: Path,
                                                monkeypatch: pytest.MonkeyPatch) -> None:
    def broken_run(*args: object, **kwargs: object) -> None:
        raise KeyError("lost")

    monkeypatch.setattr("pkgtool.commands.lint.run", broken_run)
    result = run_cli("lint", cwd=workspace)
    assert result.exit_code == ExitCode.INTERNAL
    assert "Internal error: KeyError: 'lost'. Please report this pkgtool bug" in result.stderr


@pytest.mark.parametrize(("tty", "no_color", "fmt", "output", "coloured"), [
    (True, None, "text", None, True),
    (True, "1", "text", None, False),
    (False, None, "text", None, False),
    (True, None, "json", None, False),
    (True, None, "text", Path("report.txt"), False),
])
def test_colour_only_on_a_terminal_without_no_color(monkeypatch: pytest.MonkeyPatch, tty: bool,
                                                    no_color: str | None, fmt: str,
                                                    output: Path | None, coloured: bool) -> None:
    from pkgtool import cli_lint_run

    monkeypatch.setattr(sys.stdout, "isatty", lambda: tty)
    if no_color is None:
        monkeypatch.delenv("NO_COLOR", raising=False)
    else:
        monkeypatch.setenv("NO_COLOR", no_color)
    assert cli_lint_run._colour(cli_lint_run.Format(fmt), output) is coloured


def test_large_workspaces_are_checked_in_parallel_with_the_same_report(tmp_path: Path) -> None:
    """40 packages: a process pool on a multi-core machine; the report must not change."""
    from pkgtool.commands.lint import PACKAGES_PER_WORKER

    count = 2 * PACKAGES_PER_WORKER + 8
    for index in range(count):
        _package(tmp_path / "src", f"pkg_{index:02d}", BROKEN if index % 3 == 0 else "X = 1\n")
    done = subprocess.run([sys.executable, "-m", "pkgtool", "lint", "--select", "SYN", "-f",
                           "json"], cwd=tmp_path, capture_output=True, text=True, timeout=300)
    assert done.returncode == ExitCode.FINDINGS, done.stderr
    document = json.loads(done.stdout)
    assert document["summary"]["packages"] == count
    assert [f["path"] for f in document["findings"]] == [
        f"src/pkg_{i:02d}/pkg_{i:02d}/node.py" for i in range(0, count, 3)]


def test_rosdistro_option_and_config_choose_the_target(tmp_path: Path) -> None:
    manifest = MINIMAL_MANIFEST.format(name="app").replace(
        "<exec_depend>rclpy</exec_depend>", "<exec_depend>create_msgs</exec_depend>")
    write_tree(tmp_path / "ws" / "src" / "app", {"package.xml": manifest})
    write_tree(tmp_path / "ws" / "src" / "app_msgs", {
        "package.xml": MINIMAL_MANIFEST.format(name="app_msgs")})
    ws = tmp_path / "ws"
    jazzy = run_cli("lint", "--select", "MAN022", "src/app", cwd=ws)
    assert "`create_msgs` is not a ROS package released for jazzy" in jazzy.stdout
    assert run_cli("lint", "--select", "MAN022", "--rosdistro", "humble", "src/app",
                   cwd=ws).exit_code == ExitCode.OK
    (ws / "pyproject.toml").write_text('[tool.pkgtool]\nrosdistro = "humble"\n')
    assert "No findings" in run_cli("lint", "--select", "MAN022", "src/app", cwd=ws).stdout
    wrong = run_cli("lint", "--rosdistro", "jazy", "src/app", cwd=ws)
    assert wrong.exit_code == ExitCode.USAGE and "Did you mean `jazzy`?" in wrong.stderr


def test_packages_of_the_colcon_workspace_count_as_known(tmp_path: Path) -> None:
    manifest = MINIMAL_MANIFEST.format(name="app").replace(
        "<exec_depend>rclpy</exec_depend>", "<exec_depend>app_driver</exec_depend>")
    write_tree(tmp_path / "ws" / "src" / "app", {"package.xml": manifest})
    result = run_cli("lint", "--select", "MAN022", "src/app", cwd=tmp_path / "ws")
    assert "`app_driver` is not a ROS package" in result.stdout
    write_tree(tmp_path / "ws" / "src" / "drivers" / "app_driver", {
        "package.xml": MINIMAL_MANIFEST.format(name="app_driver")})
    result = run_cli("lint", "--select", "MAN022", "src/app", cwd=tmp_path / "ws")
    assert result.exit_code == ExitCode.OK, result.output
