"""JUnit XML grading report: a test suite per submission, a test case per criterion.

A criterion below full marks is a failure; every criterion of a submission that could not be
graded is an error. Written by :func:`pkgtool.report.junit.write`.
"""

from __future__ import annotations

from collections.abc import Sequence

from pkgtool.grade.report import points
from pkgtool.grade.results import CriterionResult, SubmissionResult
from pkgtool.grade.rubric import Rubric
from pkgtool.report.junit import Case, Suite, write
from pkgtool.report.untrusted import line


def _case(result: SubmissionResult, criterion: CriterionResult) -> Case:
    feedback = "\n".join(map(line, criterion.feedback))
    if result.error:
        outcome, message = "error", f"not graded: {result.error}"
    elif not criterion.passed:
        outcome = "failure"
        message = f"{points(criterion.score)} of {points(criterion.max_score)} points"
    else:
        outcome = message = ""
    return Case(result.label, criterion.name, outcome or "passed", message,
                feedback if outcome else "", criterion.output)


def render(results: Sequence[SubmissionResult], *, rubric: Rubric) -> str:
    """The results as JUnit XML."""
    return write(f"pkgtool grade: {rubric.title}",
                 [Suite(r.label, tuple(_case(r, c) for c in r.criteria), r.seconds)
                  for r in results])
