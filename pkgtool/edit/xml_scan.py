"""Element positions in well-formed XML text: where each element starts and ends, exactly.

lxml gives line numbers only; editing needs offsets. The scanner walks the markup (comments,
processing instructions and CDATA skipped, quoted attribute values honoured) of text that
lxml has already accepted, so it only has to find boundaries, not to validate.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from pkgtool.edit.core import Edit
from pkgtool.edit.source import Source
from pkgtool.lazy_regex import lazy_pattern

_MARKUP = lazy_pattern(
    r"<!--.*?-->|<!\[CDATA\[.*?\]\]>|<\?.*?\?>|<!DOCTYPE[^>]*>"
    r"|</(?P<close>[^\s>]+)\s*>"
    r"|<(?P<open>[^\s/>!?]+)"
    r"(?P<attrs>(?:\s+[^\s=/>]+\s*=\s*(?:\"[^\"]*\"|'[^']*'))*)\s*(?P<empty>/?)>",
    re.S)
_COMMENT = lazy_pattern(r"<!--.*?-->", re.S)
_ATTRIBUTE = lazy_pattern(r"([^\s=/>]+)\s*=\s*(?:\"([^\"]*)\"|'([^']*)')")


@dataclass
class Element:
    """An element: ``start``..``end`` is all of it, ``inner_start``..``inner_end`` its content."""

    tag: str
    start: int
    end: int = -1
    inner_start: int = -1
    inner_end: int = -1
    attributes: dict[str, str] = field(default_factory=dict)
    children: list[Element] = field(default_factory=list)

    @property
    def local(self) -> str:
        """The tag without a namespace prefix."""
        return self.tag.rpartition(":")[2]


def scan(text: str) -> Element | None:
    """The root element with its descendants, or None when the markup is not balanced."""
    stack: list[Element] = []
    root: Element | None = None
    for match in _MARKUP.finditer(text):
        if match.group("open"):
            element = Element(match.group("open"), match.start(), inner_start=match.end(),
                              attributes=_attributes(match.group("attrs")))
            if stack:
                stack[-1].children.append(element)
            elif root is None:
                root = element
            else:
                return None
            if match.group("empty"):
                element.end = element.inner_end = match.end()
                element.inner_start = match.end()
            else:
                stack.append(element)
        elif match.group("close"):
            if not stack or stack[-1].tag != match.group("close"):
                return None
            element = stack.pop()
            element.inner_end, element.end = match.start(), match.end()
    return root if root is not None and not stack and root.end >= 0 else None


def insert_after(source: Source, anchor: Element, element: str, *, blank: bool = False
                 ) -> Edit:
    """An edit putting ``element`` on a new line after ``anchor``, indented like it.

    A comment sharing the anchor's line stays with the anchor.
    """
    at = anchor.end if after_on_line(source, anchor) else source.line_end(anchor.end)
    indent = source.indent_at(anchor.start) or ""
    return Edit(source.path, at, at, source.newline * (2 if blank else 1) + indent + element)


def after_on_line(source: Source, element: Element) -> str:
    """What follows ``element`` on its last line, comments left out and stripped."""
    return _COMMENT.sub("", source.text[element.end:source.line_end(element.end)]).strip()


def insert_before(source: Source, anchor: Element, element: str) -> Edit:
    """An edit putting ``element`` on its own line just before ``anchor``, indented like it."""
    indent = source.indent_at(anchor.start) or ""
    return Edit(source.path, anchor.start, anchor.start, element + source.newline + indent)


def _attributes(text: str) -> dict[str, str]:
    """Attribute values by name, entities resolved."""
    return {m.group(1): unescape(m.group(2) if m.group(2) is not None else m.group(3))
            for m in _ATTRIBUTE.finditer(text or "")}


def unescape(text: str) -> str:
    """XML text with the predefined entities and character references resolved."""
    import html

    return html.unescape(text)
