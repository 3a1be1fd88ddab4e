"""pytest plugin of the instructor-test run: results go to the grader, not to a report file.

Loaded with ``-p pkgtool.grade.hidden_plugin`` (plugin autoload is off) in the sandboxed
``python -I -m pytest`` of :mod:`pkgtool.grade.hidden`. On import, before any conftest or
test module (and so before any of the student's code) is loaded, it:

- takes the private descriptor named by ``PKGTOOL_RESULTS_FD`` and makes it close-on-exec,
  so no process the tests start inherits it;
- makes this process non-dumpable, so processes of the same uid (the student's nodes)
  cannot open its ``/proc/<pid>/fd``, read or write its memory, or ptrace it;
- appends the student's install folders (``PKGTOOL_STUDENT_PATH``) to ``sys.path``, after
  the grader's own: pytest, rclpy and every module the instructor imports come from the
  grader's environment, never from the submission.

It then writes one JSON line per event: the collected test ids, each phase's report,
collection errors, and the end of the session.
"""

from __future__ import annotations

import json
import os
import sys
from typing import Any

from pkgtool.grade.seccomp import not_dumpable

_FD = int(os.environ.pop("PKGTOOL_RESULTS_FD", "-1"))
if _FD >= 0:
    os.set_inheritable(_FD, False)
not_dumpable()
sys.path.extend(p for p in os.environ.pop("PKGTOOL_STUDENT_PATH", "").split(os.pathsep) if p)
DETAILS = 4000


def _send(record: dict[str, Any]) -> None:
    if _FD < 0:
        return
    data = (json.dumps(record) + "\n").encode()
    while data:
        data = data[os.write(_FD, data):]


def _text(report: Any) -> str:
    text = getattr(report, "longreprtext", "") or ""
    return text[-DETAILS:]


def pytest_collectreport(report: Any) -> None:
    """A test module that could not be collected (an import error, usually)."""
    if report.failed:
        _send({"kind": "collect_error", "id": report.nodeid, "details": _text(report)})


def pytest_collection_finish(session: Any) -> None:
    """The tests pytest is about to run."""
    _send({"kind": "collected", "ids": [item.nodeid for item in session.items]})


def pytest_runtest_logreport(report: Any) -> None:
    """One phase (setup, call, teardown) of one test."""
    message = ""
    crash = getattr(report.longrepr, "reprcrash", None)
    if crash is not None:
        message = str(crash.message)
    elif isinstance(report.longrepr, tuple) and len(report.longrepr) == 3:
        message = str(report.longrepr[2])  # a skip: (file, line, reason)
    _send({"kind": "report", "id": report.nodeid, "when": report.when,
           "outcome": report.outcome, "xfail": hasattr(report, "wasxfail"),
           "seconds": float(report.duration), "message": message[:500],
           "details": _text(report)})


def pytest_sessionfinish(session: Any, exitstatus: int) -> None:
    """The end of the run."""
    _send({"kind": "finished", "status": int(exitstatus)})
