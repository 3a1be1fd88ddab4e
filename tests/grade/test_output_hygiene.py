"""What `pkgtool test` and `pkgtool grade` print: clean stderr, honest JUnit, early errors."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from pkgtool import testresults as junit
from pkgtool.grade.report.package_tests import render
from pkgtool.ament.pydocstyle_runner import run_pydocstyle
from tests.grade import synthetic
from tests.helpers import run_cli

BUILD_LOG = """\
Starting >>> robot_monitor
Traceback (most recent call last):
  File "<string>", line 12
    nam e='x',
SyntaxError: invalid syntax. Perhaps you forgot a comma?
""" + "colcon traceback line\n" * 60


def test_an_unparsable_file_leaves_stderr_clean(tmp_path: Path,
                                                capfd: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "broken.py").write_text("def main(\n")
    assert run_pydocstyle(tmp_path, ["broken.py"]) == []
    assert capfd.readouterr().err == ""


def test_test_reports_count_outcomes_and_name_the_first_build_error() -> None:
    summary = junit.TestSummary(tuple(junit.TestCase(f"t.test_{outcome}", outcome, 0.1)
                                      for outcome in ("passed", "failed", "error", "skipped")))
    packages = (junit.PackageTests("good", True, summary),
                junit.PackageTests("bad", False, None, BUILD_LOG))
    suites = ET.fromstring(render("junit", packages, isolation="")).findall("testsuite")
    assert [(s.get("tests"), s.get("failures"), s.get("errors"), s.get("skipped"))
            for s in suites] == [("4", "1", "1", "1"), ("1", "0", "1", "0")]
    text = render("text", packages, isolation="")
    assert "bad: first error: SyntaxError: invalid syntax. Perhaps you forgot a comma?" in text


@pytest.mark.parametrize("args", [
    ("test", "pkg", "--output", "missing/report.txt"),
    ("grade", "pkg", "--rubric", "rubric.toml", "--output", "missing/results.json"),
])
def test_an_output_file_in_a_missing_folder_is_refused_before_any_work(
        tmp_path: Path, args: tuple[str, ...]) -> None:
    (tmp_path / "rubric.toml").write_text(synthetic.RUBRIC.format(timeout=30,
                                                                  hidden=synthetic.HIDDEN))
    synthetic.write_submission(tmp_path / "pkg", synthetic.correct())
    result = run_cli(*args, cwd=tmp_path)
    assert result.exit_code == 2 and "does not exist" in result.output, result.output
    assert "sandbox:" not in result.output and not (tmp_path / "missing").exists()
