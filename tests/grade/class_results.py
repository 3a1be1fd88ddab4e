"""A graded class written by hand for the class-report tests (scores, lint, hostile text)."""

from __future__ import annotations

from pkgtool.grade.results import CriterionResult, SubmissionResult
from pkgtool.grade.rubric import Criterion, Rubric

RUBRIC = Rubric("Lab 3: robot_monitor", (
    Criterion(kind="build", name="builds", points=2.0),
    Criterion(kind="lint", name="lint clean", points=3.0, select=("DEP", "MAN")),
    Criterion(kind="hidden", name="hidden tests", points=5.0)))
HOSTILE = "</pre><script>alert(1)</script>\x1b[2J\u202e<img src=x onerror=alert(2)>"


def _lint(*codes: str) -> CriterionResult:
    lines = tuple(f"pkg/pkg/node.py:{i + 3}: {code} something is wrong"
                  for i, code in enumerate(codes))
    return CriterionResult("lint clean", "lint", 0.0 if codes else 3.0, 3.0, lines)


def _student(label: str, build: float, lint: CriterionResult, hidden: float) -> SubmissionResult:
    criteria = (CriterionResult("builds", "build", build, 2.0, ("`colcon build` ran",)), lint,
                CriterionResult("hidden tests", "hidden", hidden, 5.0, (), "1 failed\n"))
    return SubmissionResult(label, f"submissions/{label}", sum(c.score for c in criteria), 10.0,
                            criteria, package="robot_monitor")


def results() -> list[SubmissionResult]:
    """Eight submissions: full marks, partial ones, lint findings, one ungradable, one hostile."""
    return [
        _student("alice", 2, _lint(), 5),
        _student("bob", 2, _lint("DEP001", "DEP001", "MAN004"), 5),
        _student("carol", 2, _lint("DEP001"), 2.5),
        _student("dan", 0, _lint("MAN004"), 0),
        _student("erin", 2, _lint(), 4),
        _student(HOSTILE, 2, CriterionResult("lint clean", "lint", 0.0, 3.0, (HOSTILE,)), 1),
        _student("gus", 2, _lint("SET008"), 5),
        SubmissionResult("hank", "submissions/hank.zip", 0.0, 10.0, (), error="no package.xml"),
    ]
