"""CSV gradebook: one row per submission, one column per criterion.

Written by :func:`pkgtool.report.csv.write`: labels come from students' file names, so every
text cell is neutralised against formulas.
"""

from __future__ import annotations

from collections.abc import Sequence

from pkgtool.grade.results import SubmissionResult
from pkgtool.grade.rubric import Rubric
from pkgtool.report.csv import write


def render(results: Sequence[SubmissionResult], *, rubric: Rubric) -> str:
    """The gradebook; criterion columns follow the rubric's order."""
    header = ["submission", "package", "score", "max_score", *(c.name for c in rubric.criteria),
              "error", "unchanged", "seconds"]
    return write(header, ([r.label, r.package or "", r.score, r.max_score,
                           *(c.score for c in r.criteria), r.error or "", r.unchanged, r.seconds]
                          for r in results))
