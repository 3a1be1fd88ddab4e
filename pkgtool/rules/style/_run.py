"""Shared plumbing of the style rules: which files, and tool reports as hits."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from pathlib import Path

from pkgtool.findings import Hit
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.ament.settings import style_checked_files
from pkgtool.ament.flake8_runner import StyleToolMissing, StyleViolation

Runner = Callable[[Path, list[str]], list[StyleViolation]]


def readable_sources(package: Package) -> list[str]:
    """The .py files ament's linters check that pkgtool could read (others get SYN findings)."""
    return [f for f in style_checked_files(package.files) if f in package.texts]


def tool_hits(package: Package, runner: Runner, keep: Callable[[str], bool]) -> Iterator[Hit]:
    """Run a style tool over the package; a missing tool is one hit, not a crash."""
    try:
        violations = runner(package.root, readable_sources(package))
    except StyleToolMissing as error:
        yield Hit(Span("package.xml" if package.manifest else "."), str(error),
                  'Install the style checkers: `pip install "pkgtool-ros[style]"`')
        return
    for v in violations:
        if keep(v.code):
            yield Hit(Span(v.path, v.line, v.col), f"`{v.code}` {v.text}")
