"""Render grading results: text, JSON, JUnit XML, Gradescope results.json, CSV gradebook.

Each format is a pure function ``render(results, *, rubric) -> str`` in its own module.
"""

from __future__ import annotations

import importlib
from collections.abc import Sequence

from pkgtool.grade.results import SubmissionResult
from pkgtool.grade.rubric import Rubric

FORMATS = ("text", "json", "junit", "gradescope", "csv")
SCHEMA_VERSION = 1


def render(fmt: str, results: Sequence[SubmissionResult], *, rubric: Rubric) -> str:
    """``results`` in format ``fmt`` (one of FORMATS)."""
    module = importlib.import_module(f"pkgtool.grade.report.{fmt}_report")
    return module.render(results, rubric=rubric)  # type: ignore[no-any-return]


def points(value: float) -> str:
    """A score without a needless ``.0``: 2, 1.5, 0.25."""
    return f"{value:.2f}".rstrip("0").rstrip(".")
