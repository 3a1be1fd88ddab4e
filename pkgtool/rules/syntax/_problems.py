"""What the SYN rules share: the model's parse problems of some kinds, as hits."""

from __future__ import annotations

from collections.abc import Iterator, Mapping

from pkgtool.findings import Hit
from pkgtool.model.package import Package


def problem_hits(package: Package, labels: Mapping[str, str]) -> Iterator[Hit]:
    """A hit for each problem whose kind ``labels`` names, the label before the detail."""
    for problem in package.problems:
        if problem.kind in labels:
            yield Hit(problem.span, f"{labels[problem.kind]}: {problem.detail}")
