"""Gradescope autograder ``results.json`` for one submission.

Format: https://gradescope-autograders.readthedocs.io/en/latest/specs/ (score, execution_time,
output, stdout_visibility, and tests with name, score, max_score, status, output, visibility).
Written by :func:`pkgtool.report.json.dumps`: every string is made safe.
"""

from __future__ import annotations

from collections.abc import Sequence

from pkgtool import __version__
from pkgtool.grade.results import SubmissionResult
from pkgtool.grade.rubric import Rubric
from pkgtool.report.json import dumps


def render(results: Sequence[SubmissionResult], *, rubric: Rubric) -> str:
    """The one submission of ``results`` as Gradescope's results.json."""
    if len(results) != 1:
        raise ValueError("the Gradescope format holds exactly one submission")
    result = results[0]
    summary = f"Graded by pkgtool {__version__} with the rubric `{rubric.title}`."
    if result.isolation:
        summary += f"\nSandbox: {result.isolation}"
    document = {
        "score": result.score,
        "execution_time": round(result.seconds),
        "output": f"{summary}\nNot graded: {result.error}" if result.error else summary,
        "stdout_visibility": "hidden",
        "tests": [{"name": c.name, "score": c.score, "max_score": c.max_score,
                   "status": "passed" if c.passed else "failed",
                   "output": "\n".join(c.feedback) + (f"\n\n{c.output}" if c.output else ""),
                   "visibility": c.visibility} for c in result.criteria],
    }
    return dumps(document)
