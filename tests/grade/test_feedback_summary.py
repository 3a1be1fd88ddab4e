"""``details = "summary"``: hidden-test feedback names tests and assertion messages, no source."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from pkgtool.grade.criteria import _test_outcome
from pkgtool.grade.rubric import Criterion, RubricError, parse_rubric
from pkgtool.ros.colcon import ColconRun
from pkgtool.testresults import parse_junit

SECRET = "expected_topic = '/secret_battery_topic'"
HIDDEN = f"""
def test_topic_name():
    {SECRET}
    assert False, 'the battery topic is wrong'


def test_passes():
    assert True
"""


def _real_summary(tmp_path: Path):  # type: ignore[no-untyped-def]
    """A real pytest run's JUnit report (its details hold the failing source lines)."""
    (tmp_path / "test_hidden.py").write_text(HIDDEN)
    report = tmp_path / "report.xml"
    subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider",
                    f"--junit-xml={report}", str(tmp_path / "test_hidden.py")],
                   cwd=tmp_path, capture_output=True, check=False)
    return parse_junit(report)


def test_summary_hides_source_lines_and_keeps_names_and_messages(tmp_path: Path) -> None:
    summary = _real_summary(tmp_path)
    run = ColconRun(("pytest",), 1, "", 1.0)
    full = _test_outcome(Criterion("hidden", "hidden", 2), run, summary)
    assert SECRET in full[2], "full feedback shows the traceback with its source"
    score, lines, output = _test_outcome(
        Criterion("hidden", "hidden", 2, details="summary"), run, summary)
    assert score == 1.0
    shown = "\n".join([*lines, output])
    assert SECRET not in shown and "secret_battery_topic" not in shown
    assert "test_topic_name" in output and "test_passes" in output
    assert "the battery topic is wrong" in output
    assert "the battery topic is wrong" in "\n".join(lines)


def test_details_takes_full_or_summary_only(tmp_path: Path) -> None:
    (tmp_path / "hidden").mkdir()
    base = {"criteria": [{"kind": "hidden", "points": 1, "path": "hidden", "details": "summary"}]}
    assert parse_rubric(base, base=tmp_path).criteria[0].details == "summary"
    base["criteria"][0]["details"] = "none"
    try:
        parse_rubric(base, base=tmp_path)
    except RubricError as error:
        assert "`details` must be one of full, summary" in str(error)
    else:
        raise AssertionError("an unknown details value is refused")


def test_feedback_summary_points_to_details(tmp_path: Path) -> None:
    (tmp_path / "hidden").mkdir()
    wrong = {"criteria": [{"kind": "hidden", "points": 1, "path": "hidden",
                           "feedback": "summary"}]}
    with pytest.raises(RubricError, match='write `details = "summary"`'):
        parse_rubric(wrong, base=tmp_path)
