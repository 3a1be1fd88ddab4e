"""Fixers of package.xml elements: their order, dependencies (repeated, redundant, unused, pip
names, misspelled), SPDX."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.edit.core import Fix
from pkgtool.edit.manifest import ManifestDoc
from pkgtool.edit.xml_scan import Element
from pkgtool.findings import Finding
from pkgtool.fix.common import child_at, manifest_doc, offer
from pkgtool.fix.registry import Refusal, fixer
from pkgtool.knowledge.rosdep import suggested_key
from pkgtool.knowledge.rosdistro import close_names
from pkgtool.model.package import Package
from pkgtool.records import replace
from pkgtool.rules.manifest.dependency_names import neighbours
from pkgtool.rules.manifest.non_spdx_license import spdx_spelling


def _remove_lines(package: Package, findings: list[Finding], title: str, *, safe: bool
                  ) -> Iterator[Fix]:
    doc = manifest_doc(package)
    if doc is None:
        return
    for finding in findings:
        element = child_at(doc, finding.span.line) if finding.span.path == "package.xml" else None
        if element is not None:
            yield Fix(f"{title} `{doc.text_of(element)}`", (doc.remove(element),), safe)


@fixer("MAN004", "Move the elements into the schema's order")
def element_order(package: Package, findings: list[Finding]) -> Iterator[Fix | Refusal]:
    """Reorder ``<package>``'s children as the schema's sequence wants them, each with its own
    comments; elements of one slot keep their order. Safe: the order carries no meaning."""
    doc = manifest_doc(package)
    if doc is not None and findings:
        yield from offer("Put package.xml's elements in the schema's order", doc.reorder)


@fixer("MAN013", "Remove the repeated dependency tag")
def repeated(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Delete the second and later copies (the first stays where it is)."""
    yield from _remove_lines(package, findings, "Remove repeated", safe=True)


@fixer("DEP006", "Remove the unused dependency", safe=False)
def unused(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Delete the dependency: unsafe, as something lint cannot see may still need it."""
    yield from _remove_lines(package, findings, "Remove unused", safe=False)


@fixer("MAN012", "Remove the dependency tag that `<depend>` already covers")
def redundant(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Delete the narrower tag; the ``<depend>`` it repeats stays."""
    yield from _remove_lines(package, findings, "Remove redundant", safe=True)


@fixer("MAN019", "Write the SPDX license identifier")
def spdx(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Replace a license spelling by its SPDX identifier when exactly one is meant."""
    doc = manifest_doc(package)
    if doc is None:
        return
    for finding in findings:
        element = child_at(doc, finding.span.line)
        if element is None or element.local != "license":
            continue
        suggestion = spdx_spelling(doc.text_of(element))
        if suggestion and suggestion.count("`") == 2:
            identifier = suggestion.strip("`")
            yield Fix(f"Write `{identifier}`", (doc.replace_text(element, identifier),))


@fixer("MAN018", "Write the rosdep key instead of the pip or import name")
def rosdep_key(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Rename the key rosdep data names (``numpy`` -> ``python3-numpy``); when that tag already
    declares the right key, drop the wrong one. Build types and ROS 1 packages stay manual."""
    doc = manifest_doc(package)
    if doc is None:
        return
    for finding in findings:
        element = child_at(doc, finding.span.line)
        key = suggested_key(doc.text_of(element)) if element is not None else None
        if element is not None and key is not None:
            yield _rename(doc, element, key)


@fixer("MAN021", "Write the one known name the misspelled dependency is close to",
       safe=False)
def misspelled(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Rename the key when exactly one released package, rosdep key or other workspace package
    is spelled like it. Unsafe: the key may name a package pkgtool cannot see (another
    repository, a sibling when one package is linted alone), which the rename would replace.
    With two or more near misses there is no fix: the user chooses."""
    doc = manifest_doc(package)
    if doc is None:
        return
    others = neighbours(package)
    for finding in findings:
        element = child_at(doc, finding.span.line)
        if element is None:
            continue
        close = close_names(doc.text_of(element), package.context.distro, extra=others, limit=2)
        if len(close) == 1:
            yield replace(_rename(doc, element, close[0]), safe=False)


def _rename(doc: ManifestDoc, element: Element, key: str) -> Fix:
    """Write ``key`` into the dependency ``element``, or drop it when its tag declares ``key``
    already."""
    if doc.find(element.local, key):
        return Fix(f"Remove `{doc.text_of(element)}`: `{key}` is declared",
                   (doc.remove(element),))
    return Fix(f"Write `{key}`", (doc.replace_text(element, key),))
