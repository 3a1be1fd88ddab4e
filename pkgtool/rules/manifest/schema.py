"""The package.xml schemas of REP 127, 140 and 149 (formats 1, 2, 3) as tables for the MAN rules.

Transcribed from the official XSDs (ros-infrastructure/rep, ``xsd/``); pkgtool never reads them at
run time. Patterns are the XSD patterns, implicitly anchored, applied to whitespace-collapsed
values (``xs:token``). Where an XSD pattern writes ``.`` for a literal dot, pkgtool requires the
dot, as REP 127/140/149 and catkin_pkg do.
"""

from __future__ import annotations

import functools
import re

from pkgtool.records import record
from pkgtool.lazy_regex import lazy_pattern

FORMATS = (1, 2, 3)

DEPENDS_1 = ("build_depend", "buildtool_depend", "run_depend", "test_depend", "conflict",
             "replace")
DEPENDS_2 = ("build_depend", "build_export_depend", "buildtool_depend", "buildtool_export_depend",
             "exec_depend", "depend", "doc_depend", "test_depend", "conflict", "replace")
GROUP_TAGS = ("group_depend", "member_of_group")
VERSION_ATTRIBUTES = ("version_lt", "version_lte", "version_eq", "version_gte", "version_gt")
TEXT_ONLY = frozenset({"name", "version", "maintainer", "license", "url", "author",
                       *DEPENDS_1, *DEPENDS_2, *GROUP_TAGS})
"""Elements whose content is text only (``description`` and ``export`` take any children)."""
URL_TYPES = ("website", "bugtracker", "repository")
XSI = "{http://www.w3.org/2001/XMLSchema-instance}"

# Linear-time rewrites of the XSD patterns (same languages, no nested quantifiers).
NAME = lazy_pattern(r"[a-z][a-z0-9]*(?:_[a-z0-9]+)*")
VERSION = lazy_pattern(r"(?:0|[1-9][0-9]*)(?:\.(?:0|[1-9][0-9]*)){2}")
VERSION_LIMIT = lazy_pattern(r"(?:0|[1-9][0-9]*)(?:\.(?:0|[1-9][0-9]*)){0,2}")
EMAIL = lazy_pattern(r"[-a-zA-Z0-9_%+]+(?:\.[-a-zA-Z0-9_%+]+)*"
                     r"@[-a-zA-Z0-9%]+(?:\.[-a-zA-Z0-9%]+)*\.[a-zA-Z]{2,}")
DEPEND_CONDITION = lazy_pattern(r"[$A-Za-z0-9_ \t\n\r\"'<>!=()-]*")
GROUP_CONDITION = lazy_pattern(r"[$A-Za-z0-9_ \t\n\r<>!=()-]*")


@functools.cache
def _uri_reference() -> re.Pattern[str]:
    """RFC 3986 URI-reference, which libxml2 checks ``xs:anyURI`` values against."""
    pct = r"%[0-9A-Fa-f]{2}"
    chars = r"A-Za-z0-9\-._~!$&'()*+,;="
    pchar = rf"(?:[{chars}:@]|{pct})"
    segment, segment_nz = rf"{pchar}*", rf"{pchar}+"
    segment_nz_nc = rf"(?:[{chars}@]|{pct})+"
    authority = (rf"(?:(?:[{chars}:]|{pct})*@)?"
                 rf"(?:\[[^\]]*\]|(?:[{chars}]|{pct})*)(?::[0-9]+)?")
    network = rf"//{authority}(?:/{segment})*"
    hier = rf"(?:{network}|/?(?:{segment_nz}(?:/{segment})*)?)"
    relative = rf"(?:{network}|/(?:{segment_nz}(?:/{segment})*)?|{segment_nz_nc}(?:/{segment})*)?"
    tail = rf"(?:\?(?:{pchar}|[/?])*)?(?:#(?:{pchar}|[/?\[\]])*)?"  # libxml2: [] in fragments
    return re.compile(rf"(?:[A-Za-z][A-Za-z0-9+.\-]*:{hier}|{relative}){tail}")


_URI_ESCAPED = frozenset('<>"{}|\\^`\'')


def _escaped(text: str) -> str:
    """``text`` with each character a URI must escape (controls, space, non-ASCII, quotes...)
    replaced by ``_``, as libxml2 counts them as escaped."""
    return "".join("_" if c <= " " or c >= "\x7f" or c in _URI_ESCAPED else c for c in text)


def valid_any_uri(value: str) -> bool:
    """True when lxml's XSD validation accepts ``value`` as ``xs:anyURI``.

    Like libxml2, characters URIs must escape (spaces, non-ASCII, quotes...) count as escaped.
    """
    return _uri_reference().fullmatch(_escaped(token(value))) is not None


@record
class Slot:
    """One particle of the ``<package>`` sequence: the tags it accepts and how often."""

    tags: tuple[str, ...]
    required: bool
    repeats: bool


def _sequence(depends: tuple[str, ...], groups: bool) -> tuple[Slot, ...]:
    head = [Slot(("name",), True, False), Slot(("version",), True, False),
            Slot(("description",), True, False), Slot(("maintainer",), True, True),
            Slot(("license",), True, True), Slot(("url",), False, True),
            Slot(("author",), False, True), Slot(depends, False, True)]
    tail = [Slot((tag,), False, True) for tag in GROUP_TAGS] if groups else []
    return (*head, *tail, Slot(("export",), False, False))


SEQUENCES = {1: _sequence(DEPENDS_1, False), 2: _sequence(DEPENDS_2, False),
             3: _sequence(DEPENDS_2, True)}
"""The ``<package>`` content model of each format, in the order the XSD requires."""

ORDER_HINT = {fmt: ", ".join("the dependency tags" if len(s.tags) > 1 else s.tags[0]
                             for s in slots) for fmt, slots in SEQUENCES.items()}

ALL_TAGS = frozenset(tag for slots in SEQUENCES.values() for slot in slots for tag in slot.tags)


_SLOT_INDEX = {fmt: {tag: i for i, slot in enumerate(slots) for tag in slot.tags}
               for fmt, slots in SEQUENCES.items()}


def tags_of(fmt: int) -> frozenset[str]:
    """The child elements of ``<package>`` that format ``fmt`` defines."""
    return frozenset(_SLOT_INDEX[fmt])


def formats_with(tag: str) -> tuple[int, ...]:
    """The formats that define ``tag`` as a child of ``<package>``."""
    return tuple(fmt for fmt in FORMATS if tag in _SLOT_INDEX[fmt])


def slot_index(tag: str, fmt: int) -> int | None:
    """Position of ``tag``'s slot in the format's sequence, or None if the format lacks it."""
    return _SLOT_INDEX[fmt].get(tag)


def allowed_attributes(tag: str, fmt: int) -> frozenset[str]:
    """Attributes the schema of format ``fmt`` allows on ``tag`` (``xsi:`` ones always are).

    Deliberate deviation: ``<version compatibility>`` is allowed in format 3, which REP 149
    defines, although the XSD declares the type for it and then does not use it.
    """
    if tag in DEPENDS_1 or tag in DEPENDS_2:
        return frozenset(VERSION_ATTRIBUTES + (("condition",) if fmt == 3 else ()))
    fixed = {"package": ("format",), "maintainer": ("email",), "author": ("email",),
             "url": ("type",), "group_depend": ("condition",), "member_of_group": ("condition",),
             "license": ("file",) if fmt == 3 else (),
             "version": ("compatibility",) if fmt == 3 else ()}
    return frozenset(fixed.get(tag, ()))


def token(value: str) -> str:
    """The ``xs:token`` form of a value: XML whitespace collapsed to single spaces, stripped."""
    return re.sub(r"[ \t\n\r]+", " ", value).strip(" ")


def attribute_label(key: str) -> str:
    """An lxml attribute key (``{uri}local`` for namespaced ones) as it is usually written."""
    if key.startswith("{http://www.w3.org/XML/1998/namespace}"):
        return "xml:" + key.rpartition("}")[2]
    return key.rpartition("}")[2] if key.startswith("{") else key
