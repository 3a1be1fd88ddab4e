"""No package or student can poison a report: every format of lint, test and grade, attacked.

The attack text holds a terminal escape that clears the screen, a NUL, a carriage return, a
bidirectional override, a lone surrogate, and a newline followed by lines that imitate the
report's own (a criterion at full marks, a passing test). Reports must keep all of it visible
but harmless: no control character, valid XML 1.0, no line the report did not write itself, and
no CSV cell a spreadsheet would run.
"""

from __future__ import annotations

import csv
import io
import json
import re
import xml.etree.ElementTree as ET
from pathlib import Path

import lxml.html
import pytest

from pkgtool import testresults as results
from pkgtool.grade.report import FORMATS as GRADE_FORMATS, render as render_grade
from pkgtool.grade.report.package_tests import FORMATS as TEST_FORMATS, render as render_tests
from pkgtool.grade.results import CriterionResult, SubmissionResult
from pkgtool.grade.rubric import Criterion, Rubric
from pkgtool.report import FORMATS as LINT_FORMATS
from tests.helpers import MINIMAL_MANIFEST, run_cli, write_tree

FAKE = "\n  [9/9]     Builds with colcon\nPASS test_everything (0.01 s)\nok: 99 passed"
ATTACK = "boom\x1b[2J\x00\r\x07\u202eevil\ud800" + FAKE
UNSAFE = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u202a-\u202e\u2066-\u2069\ud800-\udfff]")
FORGED = re.compile(r"^\s*(\[9/9\]|PASS\b|ok: 99)", re.MULTILINE)
RUBRIC = Rubric("demo", (Criterion("build", "Builds", 2.0), Criterion("tests", "Tests", 3.0)))


def assert_harmless(text: str, fmt: str) -> None:
    """What every format must hold, read in the way its consumers read it."""
    assert not UNSAFE.search(text), (fmt, UNSAFE.search(text))
    if fmt in ("text", "github"):
        assert not FORGED.search(text), (fmt, FORGED.search(text))
    elif fmt == "junit":
        ET.fromstring(text)
    elif fmt == "html":
        page = lxml.html.fromstring(text)
        assert not page.xpath("//script|//img|//iframe|//*[@onerror]|//*[@src]"), fmt
    elif fmt == "csv":
        for row in csv.reader(io.StringIO(text)):
            assert not any(c[:1].isspace() or c.lstrip()[:1] in "=+-@" for c in row if c
                           and not _number(c)), row
    else:
        _no_unsafe_strings(json.loads(text))
    assert "\\x1b[2J" in text or "\\u001b[2J" in text or fmt == "csv" and "\\x1b" in text, fmt


def _number(cell: str) -> bool:
    try:
        float(cell)
    except ValueError:
        return False
    return True


def _no_unsafe_strings(value: object) -> None:
    if isinstance(value, str):
        assert not UNSAFE.search(value), value
    elif isinstance(value, dict):
        for key, item in value.items():
            _no_unsafe_strings(key)
            _no_unsafe_strings(item)
    elif isinstance(value, list):
        for item in value:
            _no_unsafe_strings(item)


def test_the_check_catches_a_poisoned_report() -> None:
    """The assertions above fail on raw attack text (else every test below passes for nothing)."""
    for fmt in ("text", "junit", "json"):
        with pytest.raises(AssertionError):
            assert_harmless(f"<a>{ATTACK}</a>" if fmt == "junit" else json.dumps(ATTACK)
                            if fmt == "json" else ATTACK, fmt)
    with pytest.raises(AssertionError):
        assert_harmless("a,b\n=HYPERLINK(1),2\n", "csv")
    with pytest.raises(AssertionError):
        assert_harmless("ok \\x1b[2J" + FAKE, "text")


def _graded(label: str = ATTACK) -> list[SubmissionResult]:
    poisoned = SubmissionResult(label, f"/subs/{ATTACK}", 2.0, 5.0, (
        CriterionResult("Builds", "build", 2.0, 2.0, (ATTACK,), ATTACK),
        CriterionResult("Tests", "tests", 0.0, 3.0, (f"FAILED {ATTACK}",), ATTACK)),
        package=ATTACK, error=ATTACK, isolation=ATTACK, seconds=1.0)
    return [poisoned, SubmissionResult(f"={ATTACK}", "/subs/b", 0.0, 5.0, (), error=ATTACK)]


@pytest.mark.parametrize("fmt", GRADE_FORMATS)
def test_a_graded_result_full_of_control_text_renders_harmlessly(fmt: str) -> None:
    graded = _graded()
    assert_harmless(render_grade(fmt, graded[:1] if fmt == "gradescope" else graded,
                                 rubric=RUBRIC), fmt)


def test_the_csv_gradebook_neutralises_every_formula_start() -> None:
    labels = ["=HYPERLINK(\"http://x\")", "+1", "-2+3", "@SUM(1)", " =1", "\t=1", "\n=1"]
    graded = [SubmissionResult(label, "/s", 0.0, 5.0, ()) for label in labels]
    rows = list(csv.reader(io.StringIO(render_grade("csv", graded, rubric=RUBRIC))))[1:]
    assert [row[0] for row in rows] == ["'=HYPERLINK(\"http://x\")", "'+1", "'-2+3",
                                        "'@SUM(1)", "' =1", "'\t=1", "\\n=1"]
    assert rows[0][2:4] == ["0.0", "5.0"]  # numbers stay numbers


def _hostile_junit(path: Path) -> None:
    """A report as pytest writes it: control characters already escaped, newlines kept."""
    text = ATTACK.replace("\x1b", "#x1B").replace("\x00", "#x00").replace("\x07", "#x07")
    text = text.replace("\r", "").replace("\ud800", "")
    escaped = text.replace("&", "&amp;").replace("<", "&lt;").replace("\n", "&#10;")
    path.write_text(
        '<?xml version="1.0" encoding="utf-8"?><testsuites><testsuite name="pytest">'
        f'<testcase classname="test.test_a" name="test_x{escaped}" time="0.1">'
        f'<failure message="{escaped}">{escaped}</failure></testcase>'
        '</testsuite></testsuites>', encoding="utf-8")


@pytest.mark.parametrize("fmt", TEST_FORMATS)
def test_a_tested_package_with_a_hostile_report_and_build_log_renders_harmlessly(
        tmp_path: Path, fmt: str) -> None:
    _hostile_junit(tmp_path / "pytest.xml")
    summary = results.parse_junit(tmp_path / "pytest.xml")
    assert summary.cases and "\n" in summary.cases[0].name  # the attack reached the model
    packages = [results.PackageTests(ATTACK, True, summary, ATTACK, ATTACK, 1.0),
                results.PackageTests("broken", False, None, f"SyntaxError: {ATTACK}", None)]
    assert_harmless(render_tests(fmt, packages, isolation=ATTACK), fmt)


@pytest.fixture(scope="module")
def hostile_package(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A package whose file names and setup.py strings carry the attack into lint's findings."""
    root = tmp_path_factory.mktemp("hostile") / "pkg"
    write_tree(root, {
        "package.xml": MINIMAL_MANIFEST.format(name="pkg"),
        "setup.py": f"from setuptools import setup\nsetup(name={ATTACK[:-len(FAKE)]!r} "
                    f"{FAKE!r}, version='0.1.0')\n",
        f"pkg/node{ATTACK.replace(chr(0), '').replace(chr(0xd800), '')}.py": "def broken(:\n",
    })
    return root


@pytest.mark.parametrize("fmt", LINT_FORMATS)
def test_lint_of_a_package_with_hostile_names_and_values_reports_harmlessly(
        hostile_package: Path, fmt: str) -> None:
    result = run_cli("lint", "--format", fmt, "pkg", cwd=hostile_package.parent)
    assert result.exit_code == 1, result.output
    assert "SYN001" in result.output and "SET003" in result.output
    assert_harmless(result.output, fmt)


@pytest.fixture(scope="module")
def hostile_batch(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Submissions named by a student (folder and archive names) to poison the gradebook."""
    root = tmp_path_factory.mktemp("hostile-grade")
    names = [ATTACK.replace("\x00", "").replace("\ud800", "").replace("/", "|"),
             "=HYPERLINK(\"http:||evil\")", " @SUM(1)"]
    for name in names:
        (root / "subs" / name).mkdir(parents=True)
    (root / "rubric.toml").write_text('title = "demo"\n[[criteria]]\nkind = "build"\n'
                                      'points = 2\n')
    return root


@pytest.mark.parametrize("fmt", [f for f in GRADE_FORMATS if f != "gradescope"])
def test_grading_submissions_with_hostile_names_reports_harmlessly(
        hostile_batch: Path, fmt: str) -> None:
    result = run_cli("grade", "subs", "--batch", "--rubric", "rubric.toml", "--format", fmt,
                     cwd=hostile_batch)
    assert result.exit_code == 0, result.output
    assert_harmless(result.output, fmt)
