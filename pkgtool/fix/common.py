"""Helpers shared by fixers: package.xml, setup.py and setup.cfg as editors see them."""

from __future__ import annotations

import ast
import re
from collections.abc import Callable, Iterator, Sequence

from pkgtool.edit.changes import read_source
from pkgtool.edit.core import Edit, EditError, Fix
from pkgtool.edit.manifest import ManifestDoc
from pkgtool.edit.pysource import PyDoc
from pkgtool.edit.setup_py import SetupDoc
from pkgtool.edit.source import Source
from pkgtool.edit.xml_scan import Element
from pkgtool.findings import Finding
from pkgtool.fix.registry import Refusal
from pkgtool.knowledge.rosdistro import is_typo
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.lazy_regex import lazy_pattern


def offer(title: str, build: Callable[[], Sequence[Edit]], *, safe: bool = True
          ) -> Iterator[Fix | Refusal]:
    """The fix of ``build``'s edits; a Refusal with the editor's reason when it refuses;
    nothing when there is nothing to change."""
    try:
        edits = build()
    except EditError as error:
        yield Refusal(str(error))
        return
    if edits:
        yield Fix(title, tuple(edits), safe)


def manifest_doc(package: Package) -> ManifestDoc | None:
    """package.xml as the editor sees it; None when it is missing or not editable."""
    try:
        source = read_source(package.root, "package.xml")
        return ManifestDoc(source) if source is not None else None
    except EditError:
        return None


def setup_doc(package: Package) -> SetupDoc | None:
    """setup.py as the editor sees it; None when it is missing or its setup() is unreadable."""
    try:
        source = read_source(package.root, "setup.py")
        return SetupDoc(source, package.files) if source is not None else None
    except EditError:
        return None


def cfg_source(package: Package) -> Source | None:
    """setup.cfg's text; None when it is missing or cannot be edited."""
    try:
        return read_source(package.root, "setup.cfg")
    except EditError:
        return None


def python_nodes(package: Package, findings: list[Finding]
                 ) -> Iterator[tuple[PyDoc, Finding, list[ast.AST]]]:
    """Each finding in a Python file with the file and the ``ast`` nodes that start where it
    points (outermost first, each where its text is); files that cannot be read or parsed are
    skipped."""
    for path in sorted({f.span.path for f in findings if f.span.path.endswith(".py")}):
        try:
            source = read_source(package.root, path)
            doc = PyDoc(source) if source is not None else None
        except EditError:
            continue
        if doc is None:
            continue
        starts: dict[tuple[int, int], list[ast.AST]] = {}
        for node in ast.walk(doc.tree):
            if hasattr(node, "col_offset"):
                where = (node.lineno, node.col_offset + 1)  # type: ignore[attr-defined]
                starts.setdefault(where, []).append(node)
        for finding in findings:
            if finding.span.path == path:
                nodes = starts.get((finding.span.line, finding.span.col), [])
                yield doc, finding, [n for n in nodes if _placed(doc, n)]


def _placed(doc: PyDoc, node: ast.AST) -> bool:
    """True unless ``node`` is an expression whose text at its ``ast`` position is not that
    expression (positions inside f-strings before Python 3.12 may be off)."""
    if not isinstance(node, ast.expr):
        return True
    try:
        found = ast.parse(f"({doc.segment(node)}\n)", mode="eval").body
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return False
    return ast.dump(found) == ast.dump(node)


def child_at(doc: ManifestDoc, line: int) -> Element | None:
    """The child of ``<package>`` that starts on ``line`` (1-based), if exactly one does."""
    starts = doc.source.line_starts
    found = [c for c in doc.children if line_of(starts, c.start) == line]
    return found[0] if len(found) == 1 else None


def line_of(starts: list[int], offset: int) -> int:
    """The 1-based line of ``offset`` in a text whose lines start at ``starts``."""
    from bisect import bisect_right

    return bisect_right(starts, offset)


WRITE_ONE = lazy_pattern(r"Write `([^`]+)`")
"""The help of a finding whose fix is one name: the near miss of a misspelt one."""
WRITE_NAME = lazy_pattern(r"Write `([A-Za-z_]\w*)`")
"""The help of a finding whose fix is one Python name: the near miss of a misspelt one."""


def renames(package: Package, findings: list[Finding], wrong: re.Pattern[str],
            meant: re.Pattern[str] = WRITE_ONE, before: str = "") -> Iterator[Fix]:
    """:func:`_rename_at` for each finding whose message ``wrong`` matches (its group 1: the
    misspelt name) and whose help ``meant`` matches in full (group 1: the name meant)."""
    for finding in findings:
        help_match = meant.fullmatch(finding.fix or "")
        written = wrong.search(finding.message)
        fix = _rename_at(package, finding, written[1], help_match[1], before) \
            if help_match and written else None
        if fix is not None:
            yield fix


def _rename_at(package: Package, finding: Finding, wrong: str, meant: str,
               before: str = "") -> Fix | None:
    """``wrong`` renamed ``meant`` where the finding points, and at its related places (the
    same mistake elsewhere): at each, the one whole-name ``before + wrong`` from its column
    to the end of its line. None when a place has not exactly one, or when ``meant`` is more
    than a typo away (one edit under 14 characters, else two; a swap of neighbours is one):
    a near miss that is another word is the user's to choose."""
    if not is_typo(wrong, meant):
        return None
    edits = []
    for span in (finding.span, *finding.related):
        at = _name_at(package, span, before + wrong)
        if at is None:
            return None
        edits.append(Edit(span.path, at + len(before), at + len(before) + len(wrong), meant))
    return Fix(f"Write `{meant}` instead of `{wrong}`", tuple(edits))


def _name_at(package: Package, span: Span, text: str) -> int | None:
    """The offset of the one whole-name ``text`` from ``span``'s column to its line's end."""
    try:
        source = read_source(package.root, span.path)
    except EditError:
        return None
    if source is None or span.line < 1 or span.line > len(source.line_starts):
        return None
    start = source.offset_of_utf8(span.line, max(span.col - 1, 0))
    line = source.text[start:source.line_end(start)]
    guard = r"(?<![\w.])" if re.match(r"\w", text) else ""
    found = list(re.finditer(rf"{guard}{re.escape(text)}(?!\w)", line))
    return start + found[0].start() if len(found) == 1 else None
