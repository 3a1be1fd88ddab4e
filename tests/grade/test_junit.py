"""Reading pytest's JUnit XML: outcomes, times, and hostile or missing reports."""

from __future__ import annotations

import os

from pathlib import Path
from xml.sax.saxutils import escape

from pkgtool.testresults import parse_junit

REPORT = """<?xml version="1.0" encoding="utf-8"?>
<testsuites><testsuite name="pytest" tests="4">
  <testcase classname="test.test_a" name="test_ok" time="0.010"/>
  <testcase classname="test.test_a" name="test_bad" time="0.020">
    <failure message="assert 1 == 2">def test_bad():
&gt;   assert 1 == 2</failure></testcase>
  <testcase classname="test.test_b" name="test_boom" time="x"><error message="fixture failed"/>
  </testcase>
  <testcase classname="test.test_b" name="test_later" time="0"><skipped message="todo"/>
  </testcase>
</testsuite></testsuites>
"""


def test_outcomes_times_and_messages(tmp_path: Path) -> None:
    (tmp_path / "pytest.xml").write_text(REPORT)
    summary = parse_junit(tmp_path / "pytest.xml")
    assert summary.counts == {"passed": 1, "failed": 1, "error": 1, "skipped": 1}
    assert summary.ran == 3 and summary.passed == 1 and not summary.ok
    bad = summary.cases[1]
    assert bad.name == "test.test_a.test_bad" and bad.seconds == 0.02
    assert bad.message == "assert 1 == 2" and "assert 1 == 2" in bad.details
    assert summary.cases[2].seconds == 0.0
    assert summary.describe() == "1 passed, 1 failed, 1 error, 1 skipped"


def test_no_report_and_no_tests_are_not_a_pass(tmp_path: Path) -> None:
    missing = parse_junit(tmp_path / "pytest.xml")
    assert not missing.ok and "no tests ran" in missing.describe()
    (tmp_path / "empty.xml").write_text('<testsuites><testsuite tests="0"/></testsuites>')
    empty = parse_junit(tmp_path / "empty.xml")
    assert not empty.ok and empty.describe() == "no tests ran"


def test_only_skipped_tests_is_not_a_pass(tmp_path: Path) -> None:
    (tmp_path / "r.xml").write_text(
        '<testsuite><testcase classname="t" name="a"><skipped/></testcase></testsuite>')
    assert not parse_junit(tmp_path / "r.xml").ok


def test_entities_are_not_expanded(tmp_path: Path) -> None:
    laughs = ('<?xml version="1.0"?><!DOCTYPE l [<!ENTITY a "aaaaaaaaaa">'
              '<!ENTITY b "&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;"><!ENTITY c "&b;&b;&b;&b;&b;&b;&b;">'
              '<!ENTITY x SYSTEM "file:///etc/passwd">]>'
              '<testsuite><testcase classname="t" name="a"><failure message="&c;">&x;</failure>'
              '</testcase></testsuite>')
    (tmp_path / "r.xml").write_text(laughs)
    summary = parse_junit(tmp_path / "r.xml")
    assert "root:" not in summary.cases[0].details
    assert len(summary.cases[0].message) <= 500


def test_garbage_and_colcon_placeholders_are_problems(tmp_path: Path) -> None:
    (tmp_path / "bad.xml").write_bytes(b"\x00\x01 not xml")
    assert "cannot be read" in parse_junit(tmp_path / "bad.xml").describe()
    (tmp_path / "colcon.xml").write_text(
        '<testsuite><testcase classname="pkg.pytest" name="missing_result">'
        '<failure message="The test invocation failed without generating a result file."/>'
        '</testcase></testsuite>')
    summary = parse_junit(tmp_path / "colcon.xml")
    assert not summary.ok and "without a report" in summary.describe()


def test_a_report_linked_out_of_the_workspace_is_not_read(tmp_path: Path) -> None:
    outside = tmp_path / "secret.xml"
    outside.write_text(REPORT)
    workspace = tmp_path / "ws"
    workspace.mkdir()
    (workspace / "pytest.xml").symlink_to(outside)
    summary = parse_junit(workspace / "pytest.xml", within=workspace)
    assert not summary.cases and "is a symbolic link" in summary.describe()
    (workspace / "real.xml").write_text(REPORT)
    assert parse_junit(workspace / "real.xml", within=workspace).ran == 3


def test_a_fifo_or_a_linked_folder_for_a_report_is_refused_without_blocking(
        tmp_path: Path) -> None:
    """A FIFO where the report belongs would block a plain open forever (issue 11)."""
    workspace = tmp_path / "ws"
    (workspace / "real").mkdir(parents=True)
    (workspace / "real" / "pytest.xml").write_text(REPORT)
    os.mkfifo(workspace / "pytest.xml")
    (workspace / "linked").symlink_to(workspace / "real")
    fifo = parse_junit(workspace / "pytest.xml", within=workspace)
    assert not fifo.cases and "not a regular file" in fifo.describe()
    linked = parse_junit(workspace / "linked" / "pytest.xml", within=workspace)
    assert not linked.cases and "is a link" in linked.describe()


def test_a_collection_error_names_its_exception(tmp_path: Path) -> None:
    text = ("test/test_a.py:3: in <module>\n    from pkg.node import main\n"
            "E     File \"/ws/src/pkg/pkg/node.py\", line 4\nE   SyntaxError: expected ':'")
    case = (f'<testcase classname="test.test_{{}}" name=""><error message="collection failure">'
            f"{escape(text)}</error></testcase>")
    (tmp_path / "pytest.xml").write_text(
        f"<testsuites><testsuite>{case.format('a')}{case.format('b')}</testsuite></testsuites>")
    summary = parse_junit(tmp_path / "pytest.xml")
    assert summary.describe() == "2 errors"
    assert summary.cases[0].message == "collection failure: SyntaxError: expected ':'"
