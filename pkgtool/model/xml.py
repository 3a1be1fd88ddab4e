"""Safe XML parsing into immutable :class:`XmlElement` trees (no entities, no DTD, no network)."""

from __future__ import annotations

import re
from typing import Any

from pkgtool.model.span import ParseProblem, Span
from pkgtool.records import record
from pkgtool.safe_xml import parser
from pkgtool.lazy_regex import lazy_pattern


@record
class XmlElement:
    """An immutable copy of one XML element: enough for schema-like checks without lxml."""

    tag: str
    attributes: tuple[tuple[str, str], ...]
    text: str
    span: Span
    children: tuple[XmlElement, ...] = ()
    loose_text: tuple[tuple[int, str], ...] = ()
    """Non-blank text directly inside an element that has child elements (what ``text`` omits),
    each with the line of the node it follows; comments are not text."""

    def attribute(self, name: str) -> str | None:
        """The attribute's value, or None."""
        return dict(self.attributes).get(name)


_XML_VERSION = lazy_pattern(r"\ufeff?\s*<\?xml\s+version\s*=\s*[\"']([^\"']*)[\"']")
"""The version of a document's XML declaration (group 1)."""


def foreign_xml_version(text: str) -> re.Match[str] | None:
    """The XML declaration's version (group 1) when it is none XML has (1.0, 1.1), else
    None."""
    declared = _XML_VERSION.match(text)
    return declared if declared is not None and declared.group(1) not in ("1.0", "1.1") \
        else None


def parse_xml(path: str, text: str) -> XmlElement | ParseProblem:
    """Parse ``text``; a syntax error or a DOCTYPE/entity declaration becomes a ParseProblem.
    A declaration of an XML version other than 1.x is read as 1.0, as the ROS tools do
    (MAN027 reports it in package.xml)."""
    from lxml import etree

    if "<!DOCTYPE" in text or "<!ENTITY" in text:
        line = text[: max(text.find("<!DOCTYPE"), text.find("<!ENTITY"))].count("\n") + 1
        return ParseProblem("xml-entity", Span(path, line, 1),
                            "DOCTYPE and entity declarations are not allowed in package files")
    declared = foreign_xml_version(text)
    if declared is not None:
        # expat (Python's xml, catkin_pkg, launch) reads any number; libxml2 refuses it
        text = f"{text[:declared.start(1)]}1.0{text[declared.end(1):]}"
    try:
        root = etree.fromstring(text.encode("utf-8"), parser())
    except etree.XMLSyntaxError as error:
        line, col = error.position if error.position else (1, 1)
        message = error.msg or str(error)
        return ParseProblem("xml-syntax", Span(path, line or 1, col or 1), message)
    return _copy(path, root)


def _copy(path: str, element: Any) -> XmlElement:
    """An immutable copy of the lxml ``element`` and of its child elements."""
    if len(element) == 0:  # no child node: its text is all its text (itertext costs more)
        children: tuple[XmlElement, ...] = ()
        text = element.text or ""
    else:  # comments and processing instructions are nodes too, whose tag is no string
        children = tuple(_copy(path, c) for c in element if isinstance(c.tag, str))
        text = "".join(element.itertext()) if not children else (element.text or "")
    return XmlElement(element.tag.rpartition("}")[2],  # the local name, without a {namespace}
                      tuple(element.items()), " ".join(text.split()),
                      Span(path, element.sourceline or 1, 1), children,
                      _loose_text(element) if children else ())


def _loose_text(element: Any) -> tuple[tuple[int, str], ...]:
    """The element's own text and every child node's tail (elements, comments, PIs)."""
    pieces = [(element.sourceline or 1, element.text)]
    pieces += [(node.sourceline or 1, node.tail) for node in element]
    return tuple((line + text[: len(text) - len(text.lstrip())].count("\n"),
                  " ".join(text.split())) for line, text in pieces if text and text.strip())
