"""Run the instructor's tests against a submission so that the student cannot forge the result.

The tests are copied into the job's ``hidden`` folder (owned by the job, bound read-only
into this step only) and run by the grader's own interpreter in isolated mode (``-I``: no
``PYTHONPATH``, no ``sitecustomize``/``usercustomize`` of the submission, no current folder
on the path), with plugin autoload off and exactly the plugins the grader names (``-p``), an
empty configuration (``-c``), ``--confcutdir`` at the tests and no cache: nothing of the
submission (setup.cfg, pytest.ini, conftest.py, ``pytest11`` entry points, a package called
``pytest``, ``rclpy`` or ``std_msgs``) changes the run. Results come only from
:mod:`pkgtool.grade.hidden_plugin` through a private pipe, read after every process of the
step is dead, and only for the tests that pytest collected from the instructor's files.
"""

from __future__ import annotations

import importlib.util
import json
import os
import secrets
import sys
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

from pkgtool.grade.extract import SubmissionError
from pkgtool.safe_fs import remove_tree
from pkgtool.testresults import TestCase, TestSummary
from pkgtool.grade.sandbox import Sandbox
from pkgtool.grade.sources import copy_tree
from pkgtool.ros.colcon import ColconRun

NO_RESULT = "no result: the run ended before this test finished"


def run_hidden(box: Sandbox, source: Path, env: Mapping[str, str], student: Sequence[Path],
               test_timeout: float | None) -> tuple[ColconRun, TestSummary]:
    """Run the instructor tests of folder ``source``; ``student`` are the install folders."""
    home = box.hidden / secrets.token_hex(6)
    tests = home / source.name
    try:
        try:
            copy_tree(source, tests)
            (home / "pytest.ini").write_text("[pytest]\n")
        except (OSError, SubmissionError) as error:
            problem = f"the instructor tests could not be put in place: {error}"
            return ColconRun((), 1, problem, 0.0), TestSummary(problem=problem)
        config = home / "pytest.ini"
        box.give(home)
        command = [sys.executable, "-I", "-B", "-m", "pytest", "-c", str(config),
                   "--rootdir", str(tests), "--confcutdir", str(tests), "-p", "no:cacheprovider",
                   "-p", "pkgtool.grade.hidden_plugin", *_timeout(test_timeout), str(tests)]
        full_env = {**env, "PYTEST_DISABLE_PLUGIN_AUTOLOAD": "1",
                    "PKGTOOL_STUDENT_PATH": os.pathsep.join(map(str, student))}
        run = box.run(command, tests, full_env, channel=True, extra=[home])
    finally:
        remove_tree(home)
    return run, read_results(run.channel, source)


def timeout_args(seconds: float | None) -> list[str]:
    """pytest-timeout's per-test limit, when that plugin is installed."""
    if not seconds or importlib.util.find_spec("pytest_timeout") is None:
        return []
    return [f"--timeout={seconds:g}"]


def _timeout(seconds: float | None) -> list[str]:
    limit = timeout_args(seconds)
    return ["-p", "pytest_timeout", *limit] if limit else []


def read_results(channel: bytes, source: Path) -> TestSummary:
    """The outcome of every collected instructor test, from the plugin's JSON lines.

    Only the first list of collected ids counts, and only ids naming a test file of
    ``source``; a collected test without a result failed.
    """
    records = [_record(line) for line in channel.splitlines()]
    collected = next((r["ids"] for r in records if r.get("kind") == "collected"
                      and isinstance(r.get("ids"), list)), None)
    errors = [r for r in records if r.get("kind") == "collect_error" and _ours(r, source)]
    if collected is None and not errors:
        return TestSummary(problem="the instructor tests did not run (pytest ended before "
                                   "collecting them)")
    ids = list(dict.fromkeys(i for i in collected or [] if isinstance(i, str)
                             and _ours({"id": i}, source)))
    phases: dict[str, list[dict[str, Any]]] = {i: [] for i in ids}
    for record in records:
        if record.get("kind") == "report" and record.get("id") in phases:
            phases[record["id"]].append(record)
    cases = [TestCase(_name(r["id"]), "error", 0.0, "collection failure: "
                      + _last_error(str(r.get("details", ""))), str(r.get("details", ""))[-4000:])
             for r in errors]
    cases += [_case(i, phases[i]) for i in ids]
    return TestSummary(tuple(cases))


def _record(line: bytes) -> dict[str, Any]:
    try:
        value = json.loads(line)
    except ValueError:
        return {}
    return value if isinstance(value, dict) else {}


def _ours(record: dict[str, Any], source: Path) -> bool:
    """True when the record's test id names a file of the instructor's folder."""
    test_id = record.get("id")
    if not isinstance(test_id, str) or not test_id:
        return False
    relative = test_id.split("::", 1)[0]
    return ".." not in relative.split("/") and (source / relative).is_file()


def _name(test_id: str) -> str:
    """``test_x.py::TestA::test_b`` as pytest's JUnit names it: ``test_x.TestA.test_b``."""
    path, _, rest = test_id.partition("::")
    dotted = path.removesuffix(".py").replace("/", ".")
    return ".".join([dotted, *rest.split("::")]) if rest else dotted


def _case(test_id: str, reports: list[dict[str, Any]]) -> TestCase:
    seconds = sum(float(r.get("seconds") or 0.0) for r in reports)
    by_phase: dict[Any, dict[str, Any]] = {}
    for report in reports:
        by_phase.setdefault(report.get("when"), report)  # the first report of a phase counts
    for when in ("setup", "call", "teardown"):
        report = by_phase.get(when)
        if report is None:
            continue
        outcome = report.get("outcome")
        if outcome == "failed":
            return _result(test_id, "failed" if when == "call" else "error", seconds, report)
        if outcome == "skipped":  # xfail too
            return _result(test_id, "skipped", seconds, report)
    if by_phase.get("call", {}).get("outcome") == "passed":
        return TestCase(_name(test_id), "passed", seconds)
    return TestCase(_name(test_id), "error", seconds, NO_RESULT)


def _result(test_id: str, kind: str, seconds: float, report: dict[str, Any]) -> TestCase:
    details = str(report.get("details", ""))[-4000:]
    message = str(report.get("message") or "") or _last_error(details)
    return TestCase(_name(test_id), kind, seconds, message[:500], details)


def _last_error(details: str) -> str:
    raised = [line[1:].strip() for line in details.splitlines() if line[:2] == "E "]
    return raised[-1] if raised else (details.strip().splitlines() or [""])[-1]
