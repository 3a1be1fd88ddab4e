"""JSON grading report: versioned, every criterion with feedback and output."""

from __future__ import annotations

import json
from collections.abc import Sequence
from dataclasses import asdict

from pkgtool import __version__
from pkgtool.grade.report import SCHEMA_VERSION
from pkgtool.grade.results import SubmissionResult
from pkgtool.grade.rubric import Rubric


def render(results: Sequence[SubmissionResult], *, rubric: Rubric) -> str:
    """The results as a JSON document (``schema_version`` 1)."""
    submissions = []
    for result in results:
        entry = asdict(result)
        for criterion, data in zip(result.criteria, entry["criteria"]):
            data["passed"] = criterion.passed
            data["feedback"] = list(criterion.feedback)
        submissions.append(entry)
    document = {"schema_version": SCHEMA_VERSION, "tool": "pkgtool", "version": __version__,
                "rubric": rubric.title, "max_score": rubric.max_score,
                "submissions": submissions}
    return json.dumps(document, indent=2) + "\n"
