"""Fixers of package.xml elements: dependencies (repeated, redundant, unused, pip names), SPDX."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.edit.core import Edit, Fix
from pkgtool.findings import Finding
from pkgtool.fix.common import child_at, manifest_doc
from pkgtool.fix.registry import fixer
from pkgtool.knowledge.rosdep import suggested_key
from pkgtool.model.package import Package
from pkgtool.rules.manifest.non_spdx_license import spdx_spelling
from pkgtool.safe_xml import xml_text


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
            edit = Edit(doc.source.path, element.inner_start, element.inner_end,
                        xml_text(identifier))
            yield Fix(f"Write `{identifier}`", (edit,))


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
        if element is None or key is None:
            continue
        if doc.find(element.local, key):
            yield Fix(f"Remove `{doc.text_of(element)}`: `{key}` is declared",
                      (doc.remove(element),))
        else:
            yield Fix(f"Write `{key}`", (Edit(doc.source.path, element.inner_start,
                                              element.inner_end, xml_text(key)),))
