"""Fixers of package.xml elements: their order, dependencies (repeated, redundant, unused, pip
names, misspelled, inside ``<export>``), SPDX, the build type."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.edit.core import Edit, EditError, Fix
from pkgtool.edit.manifest import ManifestDoc
from pkgtool.edit.xml_scan import Element, insert_after
from pkgtool.findings import Finding
from pkgtool.fix.common import child_at, line_of, manifest_doc, offer
from pkgtool.fix.registry import Refusal, fixer
from pkgtool.knowledge.rosdistro import close_names
from pkgtool.model.package import Package
from pkgtool.model.xml import foreign_xml_version
from pkgtool.records import replace
from pkgtool.safe_xml import xml_text
from pkgtool.rules.dependency_names import neighbours
from pkgtool.rules.manifest.non_spdx_license import spdx_spelling
from pkgtool.rules.manifest.not_a_rosdep_key import several_keys
from pkgtool.rules.manifest.template_placeholder import is_placeholder
from pkgtool.rules.setup_values import text_of
from pkgtool.lazy_regex import lazy_pattern


def _remove_lines(package: Package, findings: list[Finding], title: str, *, safe: bool
                  ) -> Iterator[Fix]:
    doc = manifest_doc(package)
    if doc is None:
        return
    for finding in findings:
        element = child_at(doc, finding.span.line) if finding.span.path == "package.xml" else None
        if element is not None:
            yield Fix(f"{title} `{doc.text_of(element)}`", (doc.remove(element),), safe)


@fixer("MAN027", "Declare XML version 1.0")
def xml_version(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Write ``1.0`` over the version the XML declaration names. Safe: the ROS tools read
    the file as XML 1.0 already."""
    text = package.texts.get("package.xml")
    declared = foreign_xml_version(text) if text is not None and findings else None
    if declared is not None:
        yield Fix("Declare `<?xml version=\"1.0\"?>`",
                  (Edit("package.xml", declared.start(1), declared.end(1), "1.0"),))


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


_WRITE_KEY = lazy_pattern(r"Write `<\w+>([\w.+-]+)</\w+>`")
"""The fix MAN018 states when it knows the one key to write."""
_NEEDS_NONE = ("is part of the Python standard library", "is Python's standard library module",
               "is a file name, not a package")
"""How MAN018 states a dependency that declares nothing to install (a standard library
module, a file of the package): removing it changes nothing rosdep or colcon does."""


@fixer("MAN018", "Write the rosdep key instead of the pip or import name, or drop a "
       "standard library module or a file name")
def rosdep_key(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Rename the key to the one the finding names (``numpy`` -> ``python3-numpy``,
    ``opencv`` -> ``libopencv-dev`` in a CMake package); when that tag already declares the
    right key, drop the wrong one. Drop a standard library module (``math``) or a file name
    (``robot.launch.py``): there is nothing to install. Build types, ROS 1 packages and keys
    the finding leaves to the user (a Python key's name in a CMake package) stay manual."""
    doc = manifest_doc(package)
    if doc is None:
        return
    for finding in findings:
        element = child_at(doc, finding.span.line)
        written = _WRITE_KEY.fullmatch(finding.fix or "")
        keys = several_keys(doc.text_of(element)) if element is not None else []
        if element is not None and keys:
            yield _split(doc, element, keys)
        elif element is not None and written is not None:
            yield _rename(doc, element, written.group(1))
        elif element is not None and any(why in finding.message for why in _NEEDS_NONE):
            yield Fix(f"Remove `{doc.text_of(element)}`: nothing to install",
                      (doc.remove(element),))


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
        written = _WRITE_KEY.fullmatch(finding.fix or "")
        if len(close) == 1:
            yield replace(_rename(doc, element, close[0]), safe=False)
        elif not close and written is not None:  # the key of a module the code imports
            yield replace(_rename(doc, element, written.group(1)), safe=False)


def _split(doc: ManifestDoc, element: Element, keys: list[str]) -> Fix:
    """One tag per key of ``keys``, in their order, for the tag listing them all (its
    attributes kept on each); keys its tag declares elsewhere are not repeated."""
    tag, source = element.tag, doc.source
    opening = source.text[element.start:element.inner_start]
    wanted = [key for key in dict.fromkeys(keys) if not doc.find(element.local, key)]
    if not wanted:
        return Fix(f"Remove `{doc.text_of(element)}`: its keys are declared",
                   (doc.remove(element),))
    indent = source.newline + (source.indent_at(element.start) or "")
    more = indent.join(f"{opening}{xml_text(key)}</{tag}>" for key in wanted[1:])
    edits = [doc.replace_text(element, wanted[0])]
    if more:
        edits.append(insert_after(source, element, more))
    return Fix(f"Write one `<{element.local}>` per key: {', '.join(wanted)}", tuple(edits))


def _rename(doc: ManifestDoc, element: Element, key: str) -> Fix:
    """Write ``key`` into the dependency ``element``, or drop it when its tag declares ``key``
    already."""
    if doc.find(element.local, key):
        return Fix(f"Remove `{doc.text_of(element)}`: `{key}` is declared",
                   (doc.remove(element),))
    return Fix(f"Write `{key}`", (doc.replace_text(element, key),))


@fixer("MAN024", "Move the dependency out of `<export>`")
def dependency_in_export(package: Package, findings: list[Finding]) -> Iterator[Fix | Refusal]:
    """Delete the dependency tag from ``<export>`` and declare it among ``<package>``'s
    dependencies (nothing to add when that tag declares it already). Safe: it is what the
    author wrote, now where rosdep, colcon and bloom read it."""
    doc = manifest_doc(package)
    lines = {f.span.line for f in findings if f.span.path == "package.xml"}
    for export in doc.find("export") if doc is not None else ():
        for child in export.children:
            starts = doc.source.line_starts if doc is not None else []
            if doc is not None and any(line_of(starts, child.start) <= line <= line_of(
                    starts, child.inner_start) for line in lines):
                name = doc.text_of(child)
                yield from offer(f"Move `<{child.local}>{name}</{child.local}>` out of "
                                 "`<export>`", lambda child=child, name=name: [
                                     _cut(doc, child), *doc.add(child.local, name,
                                                                dict(child.attributes))])


def _cut(doc: ManifestDoc, element: Element) -> Edit:
    """Delete ``element``: its line, or up to the comment that follows it on its line."""
    text, end = doc.source.text, element.end
    rest = text[end:doc.source.line_end(end)]
    if rest.strip().startswith("<!--") and not text[doc.source.line_start(element.start):
                                                    element.start].strip():
        return Edit(doc.source.path, element.start, end + len(rest) - len(rest.lstrip()), "")
    return doc.remove(element)


@fixer("MAN015", "Declare the `ament_python` build type")
def build_type(package: Package, findings: list[Finding]) -> Iterator[Fix | Refusal]:
    """Add ``<build_type>ament_python</build_type>`` to ``<export>`` (a new one at the end of
    ``<package>`` when there is none), for a package with a setup.py. Safe: colcon built it
    with CMake, which failed. Without a setup.py the build type is the user's choice."""
    doc = manifest_doc(package)
    if doc is None or not findings:
        return
    if not package.has_file("setup.py"):
        yield Refusal("the package has neither setup.py nor CMakeLists.txt: add the build "
                      "type it is built with by hand.")
        return
    if package.manifest is not None and package.manifest.is_ros1:
        yield Refusal("a catkin package needs a CMakeLists.txt, not a build type: write it "
                      "by hand.")
        return
    yield from offer("Declare `<build_type>ament_python</build_type>`", lambda: _build_type(doc))


def _build_type(doc: ManifestDoc) -> list[Edit]:
    source, exports = doc.source, doc.find("export")
    children = doc.children
    if not children:
        raise EditError("package.xml's `<package>` has no children: write it by hand.")
    indent = source.indent_at(children[-1].start) or "  "
    element = "<build_type>ament_python</build_type>"
    if not exports:
        newline = source.newline
        return [insert_after(source, children[-1], f"<export>{newline}{indent * 2}{element}"
                             f"{newline}{indent}</export>")]
    export = exports[0]
    if export.inner_start == export.end:
        raise EditError("package.xml has an empty `<export/>`: write the build type into it "
                        "by hand.")
    if export.children:
        return [insert_after(source, export.children[-1], element)]
    at, end = export.inner_start, source.line_end(export.inner_start)
    rest = source.text[at:end].strip()
    if not rest or rest.startswith("<!--") and rest.endswith("-->") and end < export.end:
        return [Edit(source.path, end, end, source.newline + indent * 2 + element)]
    return [Edit(source.path, at, at, source.newline + indent * 2 + element + source.newline +
                 indent)]


@fixer("MAN017", "Write setup.py's description or license over the placeholder")
def placeholder(package: Package, findings: list[Finding]) -> Iterator[Fix | Refusal]:
    """Replace a placeholder ``<description>`` or ``<license>`` by what setup.py's
    ``description`` or ``license`` says, when that is a real value (one license: a list
    needs a tag each; its SPDX identifier when it names exactly one). Safe: only metadata
    changes, and the author wrote it. Placeholder emails, and placeholders setup.py does not
    answer, are the author's to fill in."""
    doc = manifest_doc(package)
    for finding in findings if doc is not None else ():
        element = child_at(doc, finding.span.line) if doc is not None else None
        if doc is None or element is None or element.local not in ("description", "license"):
            continue
        text = setup_answer(package, element.local)
        if text is None:
            yield Refusal(f"only the author knows the package's {element.local}: write it into "
                          "package.xml (setup.py's is no help).")
            continue
        spdx = spdx_spelling(text) if element.local == "license" else None
        text = spdx.strip("`") if spdx and spdx.count("`") == 2 else text
        yield Fix(f"Write setup.py's {element.local} `{text}`", (doc.replace_text(element, text),))


def setup_answer(package: Package, tag: str) -> str | None:
    """What setup.py says for a placeholder ``<description>`` or ``<license>`` (one real
    value: not a placeholder itself, not a list of licenses); None when it is no help."""
    found = text_of(getattr(package.setup_py, tag, None)) if package.setup_py else None
    text = " ".join(found[0].split()) if found else ""
    if not text or is_placeholder(text) or tag == "license" and "," in text:
        return None
    return text
