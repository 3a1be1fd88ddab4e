"""``pkgtool lint --fix``, ``--diff`` and ``--unsafe-fixes`` on packages with fixable findings."""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from pkgtool.fix.registry import fixers
from pkgtool.rules.registry import load_all
from tests.helpers import correct_package_files, run_cli, write_tree

RCLPY = "  <exec_depend>rclpy</exec_depend>\n"
NUMPY_TALKER = "import numpy\n"


@pytest.fixture()
def package(tmp_path: Path) -> Path:
    """A correct package with a repeated dependency (MAN013) and an undeclared import (DEP001)."""
    root = tmp_path / "pkg"
    files = correct_package_files("pkg")
    manifest = str(files["package.xml"])
    files["package.xml"] = manifest.replace(RCLPY, RCLPY * 2)
    files["pkg/helper.py"] = NUMPY_TALKER
    write_tree(root, files)
    return root


def _snapshot(root: Path) -> dict[str, bytes]:
    return {p.relative_to(root).as_posix(): p.read_bytes()
            for p in sorted(root.rglob("*")) if p.is_file()}


def test_every_fixer_belongs_to_a_registered_rule() -> None:
    assert set(fixers()) <= set(load_all())


def test_diff_prints_the_fixes_and_writes_nothing(package: Path) -> None:
    before = _snapshot(package)
    result = run_cli("lint", "--diff", "pkg", cwd=package.parent)
    assert result.exit_code == 1, result.output
    assert "--- a/pkg/package.xml" in result.stdout
    assert "-  <exec_depend>rclpy</exec_depend>" in result.stdout
    assert "+  <exec_depend>python3-numpy</exec_depend>" in result.stdout
    assert _snapshot(package) == before


def test_diff_shows_every_round_of_fix(tmp_path: Path) -> None:
    """Fixes that overlap take one round each; ``--diff`` shows what ``--fix`` writes in all
    of them, not the first round alone."""
    files = correct_package_files("pkg")
    files["package.xml"] = str(files["package.xml"]).replace(
        "  <exec_depend>launch_ros</exec_depend>\n",
        "  <exec_depend>launch_ros</exec_depend>\n  <exec_depend>os</exec_depend>\n")
    files["pkg/helper.py"] = "import numpy\nimport yaml\nimport scipy\n"
    write_tree(tmp_path / "shown" / "pkg", files)
    write_tree(tmp_path / "fixed" / "pkg", files)
    shown = run_cli("lint", "--diff", "pkg", cwd=tmp_path / "shown")
    run_cli("lint", "--fix", "pkg", cwd=tmp_path / "fixed")
    before = str(files["package.xml"]).splitlines(keepends=True)
    after = (tmp_path / "fixed" / "pkg" / "package.xml").read_text().splitlines(keepends=True)
    added = [line for line in after if line not in before]
    removed = [line for line in before if line not in after]
    assert len(added) == 3 and removed == ["  <exec_depend>os</exec_depend>\n"], after
    assert all(f"+{line}" in shown.stdout for line in added), shown.stdout
    assert f"-{removed[0]}" in shown.stdout, shown.stdout
    assert (tmp_path / "shown" / "pkg" / "package.xml").read_text() == files["package.xml"]


def test_diff_reads_the_files_lint_reads(tmp_path: Path) -> None:
    """``--diff`` fixes a copy of the files lint reads: a folder linked in from elsewhere in
    the repository is followed (its import needs a key), a named pipe is not copied."""
    (tmp_path / "shared" / "helpers").mkdir(parents=True)
    (tmp_path / "shared" / "helpers" / "util.py").write_text("import yaml\n")
    (tmp_path / "shared" / "helpers" / "__init__.py").write_text("")
    write_tree(tmp_path / "pkg", correct_package_files("pkg"))
    (tmp_path / "pkg" / "pkg" / "helpers").symlink_to(tmp_path / "shared" / "helpers")
    os.mkfifo(tmp_path / "pkg" / "pkg" / "pipe")
    shown = run_cli("lint", "--diff", "pkg", cwd=tmp_path)
    assert shown.exit_code == 1, shown.output
    assert "+  <exec_depend>python3-yaml</exec_depend>" in shown.stdout


def test_fix_repairs_then_reports_what_is_left_and_is_idempotent(package: Path) -> None:
    untouched = {k: v for k, v in _snapshot(package).items() if k != "package.xml"}
    first = run_cli("lint", "--fix", "--strict", "pkg", cwd=package.parent)
    assert first.exit_code == 0, first.output
    assert "No findings" in first.stdout
    text = (package / "package.xml").read_text()
    assert text.count(RCLPY) == 1 and "<exec_depend>python3-numpy</exec_depend>" in text
    assert {k: v for k, v in _snapshot(package).items() if k != "package.xml"} == untouched
    fixed = _snapshot(package)
    again = run_cli("lint", "--fix", "--strict", "pkg", cwd=package.parent)
    assert again.exit_code == 0, again.output
    assert _snapshot(package) == fixed


def test_unused_dependency_goes_only_with_unsafe_fixes(tmp_path: Path) -> None:
    root = tmp_path / "pkg"
    files = correct_package_files("pkg")
    files["package.xml"] = str(files["package.xml"]).replace(
        RCLPY, RCLPY + "  <exec_depend>python3-yaml</exec_depend>\n")
    write_tree(root, files)
    run_cli("lint", "--fix", "pkg", cwd=tmp_path)
    assert "python3-yaml" in (root / "package.xml").read_text()
    result = run_cli("lint", "--fix", "--unsafe-fixes", "pkg", cwd=tmp_path)
    assert result.exit_code == 0, result.output
    assert "python3-yaml" not in (root / "package.xml").read_text()
    assert (root / "package.xml").read_text() == files["package.xml"].replace(
        "  <exec_depend>python3-yaml</exec_depend>\n", "")


def test_clean_package_is_left_byte_for_byte(tmp_path: Path) -> None:
    root = tmp_path / "pkg"
    write_tree(root, correct_package_files("pkg"))
    before = _snapshot(root)
    result = run_cli("lint", "--fix", "--unsafe-fixes", "pkg", cwd=tmp_path)
    assert result.exit_code == 0, result.output
    assert _snapshot(root) == before


def test_reports_mark_fixable_findings(package: Path) -> None:
    text = run_cli("lint", "pkg", cwd=package.parent).stdout
    assert "MAN013 [*]" in text and "fixable with `--fix`" in text
    document = json.loads(run_cli("lint", "-f", "json", "pkg", cwd=package.parent).stdout)
    marks = {f["rule"]: f["fixable"] for f in document["findings"]}
    assert marks["MAN013"] == "safe" and marks["DEP001"] == "safe"
    sarif = json.loads(run_cli("lint", "-f", "sarif", "pkg", cwd=package.parent).stdout)
    results = sarif["runs"][0]["results"]
    assert {r["properties"].get("fixable") for r in results if r["ruleId"] == "MAN013"} == \
        {"safe"}


def test_findings_the_fixer_will_refuse_are_not_offered(tmp_path: Path) -> None:
    files = correct_package_files("pkg")
    files["package.xml"] = files["package.xml"].replace(
        "<license>Apache-2.0</license>", "<license>TODO: License declaration</license>")
    files["setup.py"] = files["setup.py"].replace(
        "license='Apache-2.0'", "license='TODO: License declaration'")
    write_tree(tmp_path / "pkg", files)
    text = run_cli("lint", "pkg", cwd=tmp_path).stdout
    assert "MAN017 `<license>`" in text and "fixable" not in text  # setup.py is no help
    document = json.loads(run_cli("lint", "-f", "json", "pkg", cwd=tmp_path).stdout)
    assert [f["fixable"] for f in document["findings"] if f["rule"] == "MAN017"] == [None]


def test_a_symlinked_manifest_out_of_the_package_is_not_written(package: Path) -> None:
    outside = package.parent / "outside.xml"
    outside.write_bytes((package / "package.xml").read_bytes())
    (package / "package.xml").unlink()
    os.symlink(outside, package / "package.xml")
    before = outside.read_bytes()
    result = run_cli("lint", "--fix", "pkg", cwd=package.parent)
    assert result.exception is None or isinstance(result.exception, SystemExit)
    assert outside.read_bytes() == before


def test_malformed_manifest_gives_findings_not_a_traceback(package: Path) -> None:
    (package / "package.xml").write_text("<package><name>pkg</name>")
    before = _snapshot(package)
    result = run_cli("lint", "--fix", "pkg", cwd=package.parent)
    assert result.exit_code == 1, result.output
    assert "Traceback" not in result.output
    assert _snapshot(package) == before
