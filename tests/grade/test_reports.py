"""Report formats of `pkgtool grade`: contracts on keys, shape and escaping."""

from __future__ import annotations

import csv
import io
import json
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from pkgtool.grade.report import FORMATS, render
from pkgtool.grade.results import CriterionResult, SubmissionResult
from pkgtool.grade.rubric import Criterion, Rubric

RUBRIC = Rubric("demo", (Criterion("build", "Builds", 2.0),
                         Criterion("tests", "Tests", 3.0, visibility="after_published")))


def _result(label: str = "alice", tests: float = 1.5) -> SubmissionResult:
    return SubmissionResult(
        label, f"/subs/{label}", 2 + tests, 5.0,
        (CriterionResult("Builds", "build", 2.0, 2.0, ("`colcon build` succeeded in 1.0 s",)),
         CriterionResult("Tests", "tests", tests, 3.0, ("1 passed, 1 failed",),
                         "FAILED test_x", "after_published")),
        package="talker_pkg", isolation="namespaces", seconds=4.2)


def test_gradescope_results_json_follows_the_documented_format() -> None:
    document = json.loads(render("gradescope", [_result()], rubric=RUBRIC))
    assert set(document) == {"score", "execution_time", "output", "stdout_visibility", "tests"}
    assert document["score"] == 3.5 and document["execution_time"] == 4
    assert [set(t) for t in document["tests"]] == [
        {"name", "score", "max_score", "status", "output", "visibility"}] * 2
    tests = document["tests"][1]
    assert (tests["score"], tests["max_score"], tests["status"]) == (1.5, 3.0, "failed")
    assert tests["visibility"] == "after_published" and "FAILED test_x" in tests["output"]
    with pytest.raises(ValueError):
        render("gradescope", [_result(), _result("bob")], rubric=RUBRIC)


def test_json_is_versioned_and_complete() -> None:
    document = json.loads(render("json", [_result()], rubric=RUBRIC))
    assert document["schema_version"] == 1 and document["max_score"] == 5.0
    entry = document["submissions"][0]
    assert {"label", "path", "score", "max_score", "package", "error", "unchanged",
            "isolation", "seconds", "criteria"} <= set(entry)
    assert entry["criteria"][1]["passed"] is False


def test_junit_marks_lost_points_as_failures() -> None:
    root = ET.fromstring(render("junit", [_result(), _result("bob", 3.0)], rubric=RUBRIC))
    suites = root.findall("testsuite")
    assert [s.get("failures") for s in suites] == ["1", "0"]
    assert suites[0].find("testcase[@name='Tests']/failure").get("message") == "1.5 of 3 points"


def test_csv_gradebook_has_a_column_per_criterion_and_defuses_formulas() -> None:
    rows = list(csv.reader(io.StringIO(render("csv", [_result("=HYPERLINK(1)")],
                                              rubric=RUBRIC))))
    assert rows[0][:6] == ["submission", "package", "score", "max_score", "Builds", "Tests"]
    assert rows[1][0] == "'=HYPERLINK(1)" and rows[1][4:6] == ["2.0", "1.5"]


def test_text_has_details_and_a_summary_table() -> None:
    text = render("text", [_result(), _result("bob", 3.0)], rubric=RUBRIC)
    assert "alice (talker_pkg): 3.5 / 5" in text and "[1.5/3]" in text
    assert "demo: 2 submissions" in text and "full marks" in text


def test_every_format_renders_an_ungraded_submission() -> None:
    broken = SubmissionResult("eve", "/subs/eve.zip", 0.0, 5.0, (
        CriterionResult("Builds", "build", 0.0, 2.0, ("Not graded: unsafe archive",)),
        CriterionResult("Tests", "tests", 0.0, 3.0, ("Not graded: unsafe archive",))),
        error="unsafe archive")
    for fmt in FORMATS:
        assert "unsafe archive" in render(fmt, [broken], rubric=RUBRIC), fmt


def test_formats_match_the_cli(tmp_path: Path) -> None:
    from pkgtool.cli_grade import Format

    assert tuple(f.value for f in Format) == FORMATS
