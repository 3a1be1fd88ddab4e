"""Fixers that declare what code imports: the rosdep key as the right ``*_depend``."""

from __future__ import annotations

from collections.abc import Iterable, Iterator

from pkgtool.edit.core import EditError, Fix
from pkgtool.findings import Finding
from pkgtool.fix.common import manifest_doc
from pkgtool.fix.registry import fixer
from pkgtool.model.package import Package
from pkgtool.rules.imports import Need, needs, test_code, unmet_runtime_needs


def _declare(package: Package, findings: list[Finding], found: Iterable[Need], tag: str
             ) -> Iterator[Fix]:
    doc = manifest_doc(package)
    if doc is None:
        return
    wanted = {(f.span.path, f.span.line, f.span.col) for f in findings}
    keys = []
    for need in found:
        span = need.imported.span
        if need.kind != "unknown" and (span.path, span.line, span.col) in wanted \
                and need.key not in keys:
            keys.append(need.key)
    for key in keys:
        try:
            edits = doc.add(tag, key)
        except EditError:
            continue
        if edits:
            yield Fix(f"Add `<{tag}>{key}</{tag}>`", tuple(edits))


@fixer("DEP001", "Add an `<exec_depend>` with the rosdep key")
def undeclared(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Declare each import's rosdep key for run time."""
    yield from _declare(package, findings, unmet_runtime_needs(package), "exec_depend")


@fixer("DEP003", "Add a `<test_depend>` with the rosdep key")
def undeclared_test(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Declare each test import's rosdep key for tests."""
    found = (need for module in test_code(package) for need in needs(package, module))
    yield from _declare(package, findings, found, "test_depend")
