"""Edits of package.xml: add and remove children of ``<package>`` where the schema wants them.

A new element goes into the slot REP 140/149's sequence assigns its tag, next to its own kind,
with the indentation and line breaks of the file. Elements of one dependency tag stay sorted
when they were sorted; a new kind of dependency starts its own group (after a blank line when
the file separates its groups so). Removing an element removes its whole line.
"""

from __future__ import annotations

import re
from bisect import bisect_right

from pkgtool.safe_xml import xml_text
from pkgtool.edit.core import Edit, EditError
from pkgtool.edit.source import Source
from pkgtool.edit.xml_scan import (Element, after_on_line, insert_after, insert_before, scan,
                                   unescape)
from pkgtool.rules.manifest.schema import slot_index

DEPEND_ORDER = ("buildtool_depend", "buildtool_export_depend", "build_depend",
                "build_export_depend", "depend", "exec_depend", "run_depend", "test_depend",
                "doc_depend", "conflict", "replace")
"""The order ``ros2 pkg create`` and catkin write dependency tags in (the schema allows any)."""


class ManifestDoc:
    """package.xml text with the positions of ``<package>``'s children."""

    def __init__(self, source: Source) -> None:
        root = scan(source.text)
        if root is None or root.local != "package":
            raise EditError(f"`{source.path}` is not a well-formed package.xml with a "
                            "`<package>` root: fix it (pkgtool lint says where) and retry.")
        self.source = source
        self.root = root
        value = root.attributes.get("format", "1").strip()
        self.format = int(value) if value in ("1", "2", "3") else 3

    @property
    def children(self) -> list[Element]:
        """The element children of ``<package>`` in document order."""
        return self.root.children

    def text_of(self, element: Element) -> str:
        """An element's text, entities resolved and whitespace collapsed."""
        return " ".join(unescape(self.source.text[element.inner_start:element.inner_end]).split())

    def find(self, tag: str, text: str | None = None) -> list[Element]:
        """Children with ``tag`` (and, if given, that text)."""
        return [c for c in self.children
                if c.local == tag and (text is None or self.text_of(c) == text)]

    # Adding ------------------------------------------------------------------------------

    def add(self, tag: str, text: str, attributes: dict[str, str] | None = None) -> list[Edit]:
        """Insert ``<tag attrs>text</tag>``; nothing when an equal element is there already."""
        attributes = attributes or {}
        if any(c.attributes == attributes for c in self.find(tag, text)):
            return []
        if slot_index(tag, self.format) is None:
            raise EditError(f"`<{tag}>` does not exist in package.xml format {self.format}: "
                            "pkgtool does not add it.")
        attrs = "".join(f' {k}="{xml_text(v)}"' for k, v in attributes.items())
        element = f"<{tag}{attrs}>{xml_text(text)}</{tag}>"
        same = self.find(tag)
        if same:
            return [self._beside_sibling(same, element, text)]
        return [self._new_group(tag, element)]

    def _beside_sibling(self, same: list[Element], element: str, text: str) -> Edit:
        names = [self.text_of(c).lower() for c in same]
        index = len(same)
        if names == sorted(names):
            index = bisect_right(names, text.lower())
        if index == 0:
            return insert_before(self.source, same[0], element)
        return insert_after(self.source, same[index - 1], element)

    def _new_group(self, tag: str, element: str) -> Edit:
        rank = _rank(tag, self.format)
        before = [c for c in self.children if _rank(c.local, self.format) <= rank]
        if before:
            anchor = before[-1]
            return insert_after(self.source, anchor, element, blank=self._blank_after(anchor))
        first = self.children[0] if self.children else None
        if first is None:
            at = self.root.inner_start
            return Edit(self.source.path, at, at, self.source.newline + "  " + element +
                        self.source.newline)
        return insert_before(self.source, first, element)

    def _blank_after(self, anchor: Element) -> bool:
        """True when a blank line follows ``anchor`` before the next element or the end."""
        following = [c.start for c in self.children if c.start > anchor.start]
        stop = following[0] if following else self.root.inner_end
        gap = self.source.text[insert_after(self.source, anchor, "").start:stop]
        return any(not line.strip() for line in re.split(r"\r\n|\r|\n", gap)[1:-1])

    def retag(self, element: Element, tag: str) -> list[Edit]:
        """Edits renaming ``element`` to ``tag``; attributes, text and layout stay."""
        path, name = self.source.path, element.tag
        edits = [Edit(path, element.start + 1, element.start + 1 + len(name), tag)]
        if element.inner_end != element.end:  # not an empty element: the end tag too
            at = element.inner_end + 2
            edits.append(Edit(path, at, at + len(name), tag))
        return edits

    def replace_text(self, element: Element, text: str) -> Edit:
        """An edit writing ``text`` (escaped) as the content of ``element``."""
        return Edit(self.source.path, element.inner_start, element.inner_end, xml_text(text))

    # Ordering ----------------------------------------------------------------------------

    def reorder(self) -> list[Edit]:
        """One edit putting ``<package>``'s children in the schema's order, or none when they
        are in it. The sort is stable (elements of one slot, such as the dependency tags, keep
        their order) and each element moves with its own lines: the comments and blank lines
        just above it and a comment after it on its last line. Refused when an element shares
        a line with another element or with ``<package>``'s tags."""
        children = self.children
        ranks = [slot_index(c.local, self.format) for c in children]
        if any(rank is None for rank in ranks):
            raise EditError("package.xml holds an element its format does not define: fix "
                            "that first (MAN005/MAN006 say which).")
        order = sorted(range(len(children)), key=lambda i: ranks[i])
        if order == list(range(len(children))):
            return []
        bounds = [self._own_lines(child) for child in children]
        starts = [bounds[0][0]] + [end for _, end in bounds[:-1]]
        chunks = [self.source.text[start:end] for start, (_, end) in zip(starts, bounds)]
        return [Edit(self.source.path, starts[0], bounds[-1][1],
                     "".join(chunks[i] for i in order))]

    def _own_lines(self, element: Element) -> tuple[int, int]:
        """Start of ``element``'s first line and end of its last (line break included)."""
        text, source = self.source.text, self.source
        first, last = source.line_start(element.start), source.line_end(element.end)
        if text[first:element.start].strip() or after_on_line(source, element) \
                or last >= len(text):
            raise EditError(f"`<{element.local}>` shares its line with other markup: put each "
                            "child of `<package>` on lines of its own to have it reordered.")
        return first, last + len(source.newline)

    # Removing ----------------------------------------------------------------------------

    def remove(self, element: Element) -> Edit:
        """Delete ``element``; its whole line when nothing else stands on it."""
        text = self.source.text
        start, end = element.start, element.end
        line_start = self.source.line_start(start)
        line_end = self.source.line_end(end)
        if not text[line_start:start].strip() and not text[end:line_end].strip():
            start = line_start
            end = line_end + len(self.source.newline) if line_end < len(text) else line_end
            if self._blank(line_start, before=True) and self._blank(end, before=False):
                end = self.source.line_end(end) + len(self.source.newline)
        return Edit(self.source.path, start, min(end, len(text)), "")

    def _blank(self, offset: int, *, before: bool) -> bool:
        """True when the line before (or at) ``offset`` is blank."""
        text = self.source.text
        if before:
            if offset == 0:
                return False
            previous = self.source.line_start(offset - 1)
            return not text[previous:offset].strip()
        if offset >= len(text):
            return False
        return not text[offset:self.source.line_end(offset)].strip()


def _rank(tag: str, fmt: int) -> tuple[int, int]:
    """Where ``tag`` sorts among ``<package>``'s children: schema slot, then the usual order."""
    slot = slot_index(tag, fmt)
    order = DEPEND_ORDER.index(tag) if tag in DEPEND_ORDER else 0
    return (slot if slot is not None else -1, order)
