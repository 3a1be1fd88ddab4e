"""Fixers that remove package.xml elements: repeated and unused dependencies."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.edit.core import Fix
from pkgtool.findings import Finding
from pkgtool.fix.common import child_at, manifest_doc
from pkgtool.fix.registry import fixer
from pkgtool.model.package import Package


def _remove_lines(package: Package, findings: list[Finding], title: str, *, safe: bool
                  ) -> Iterator[Fix]:
    doc = manifest_doc(package)
    if doc is None:
        return
    for finding in findings:
        element = child_at(doc, finding.span.line) if finding.span.path == "package.xml" else None
        if element is not None:
            yield Fix(f"{title} `{doc.text_of(element)}`", (doc.remove(element),), safe)


@fixer("MAN013", "Remove the repeated dependency tag")
def repeated(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Delete the second and later copies (the first stays where it is)."""
    yield from _remove_lines(package, findings, "Remove repeated", safe=True)


@fixer("DEP006", "Remove the unused dependency", safe=False)
def unused(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Delete the dependency: unsafe, as something lint cannot see may still need it."""
    yield from _remove_lines(package, findings, "Remove unused", safe=False)
