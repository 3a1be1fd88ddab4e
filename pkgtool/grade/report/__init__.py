"""Render grading results: text, JSON, JUnit XML, Gradescope results.json, CSV, HTML.

Each format is a pure function ``render(results, *, rubric) -> str`` in the module of its name,
written with the format's one writer in :mod:`pkgtool.report`; :mod:`.package_tests` renders
``pkgtool test``. What a student controls (labels, package names, error text, test names and
output) is made safe by those writers.
"""

from __future__ import annotations

import importlib
from collections.abc import Sequence

from pkgtool.grade.results import SubmissionResult
from pkgtool.grade.rubric import Rubric

FORMATS = ("text", "json", "junit", "gradescope", "csv", "html")


def render(fmt: str, results: Sequence[SubmissionResult], *, rubric: Rubric) -> str:
    """``results`` in format ``fmt`` (one of FORMATS)."""
    if fmt not in FORMATS:
        raise ValueError(f"unknown report format {fmt!r}")
    module = importlib.import_module(f"pkgtool.grade.report.{fmt}")
    return module.render(results, rubric=rubric)  # type: ignore[no-any-return]


def points(value: float) -> str:
    """A score without a needless ``.0``: 2, 1.5, 0.25."""
    return f"{value:.2f}".rstrip("0").rstrip(".")
