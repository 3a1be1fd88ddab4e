"""JSON grading report: every submission with every criterion's feedback and output.

The document of docs/json.md (``"command": "grade"``), written by
:func:`pkgtool.report.json.document`.
"""

from __future__ import annotations

from collections.abc import Sequence

from pkgtool.grade.results import CriterionResult, SubmissionResult
from pkgtool.grade.rubric import Rubric
from pkgtool.report.json import document


def _criterion(criterion: CriterionResult) -> dict[str, object]:
    return {"name": criterion.name, "kind": criterion.kind, "score": criterion.score,
            "max_score": criterion.max_score, "feedback": list(criterion.feedback),
            "output": criterion.output, "visibility": criterion.visibility,
            "passed": criterion.passed}


def _submission(result: SubmissionResult) -> dict[str, object]:
    return {"label": result.label, "path": result.path, "score": result.score,
            "max_score": result.max_score, "criteria": list(map(_criterion, result.criteria)),
            "package": result.package, "error": result.error, "isolation": result.isolation,
            "seconds": result.seconds, "unchanged": result.unchanged}


def render(results: Sequence[SubmissionResult], *, rubric: Rubric) -> str:
    """The results as pkgtool's JSON document."""
    return document("grade", {"rubric": rubric.title, "max_score": rubric.max_score,
                              "submissions": list(map(_submission, results))})
