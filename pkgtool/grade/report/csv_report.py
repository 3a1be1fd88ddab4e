"""CSV gradebook: one row per submission, one column per criterion."""

from __future__ import annotations

import csv
import io
from collections.abc import Sequence

from pkgtool.grade.results import SubmissionResult
from pkgtool.grade.rubric import Rubric


def render(results: Sequence[SubmissionResult], *, rubric: Rubric) -> str:
    """The gradebook; criterion columns follow the rubric's order."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    names = [c.name for c in rubric.criteria]
    writer.writerow(["submission", "package", "score", "max_score", *names, "error",
                     "unchanged", "seconds"])
    for r in results:
        writer.writerow([_cell(r.label), _cell(r.package or ""), r.score, r.max_score,
                         *(c.score for c in r.criteria), _cell(r.error or ""), r.unchanged,
                         r.seconds])
    return buffer.getvalue()


def _cell(text: str) -> str:
    """Text a spreadsheet will not run as a formula (labels come from students' file names)."""
    return f"'{text}" if text[:1] in ("=", "+", "-", "@", "\t", "\r") else text
