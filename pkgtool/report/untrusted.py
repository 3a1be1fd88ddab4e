"""Text a package or a student controls, made safe to print in any report format.

Paths, package names, messages quoting package files, test names, error text and build logs
can hold any character. Every writer passes such text through :func:`line` (a field that must
stay on its line), :func:`block` (text kept as several lines) or :func:`quoted` (several lines
of a text report). What comes out holds no
terminal escape, no carriage return or other control character, no character that is invalid
in XML 1.0 and no bidirectional override; each becomes a visible escape such as ``\\x1b``, so
a reader still sees that it was there.
"""

from __future__ import annotations

import re
from pkgtool.lazy_regex import lazy_pattern

_UNSAFE = lazy_pattern(
    "[\x00-\x08\x0b-\x1f\x7f-\x9f"  # control characters but tab and newline (C0, DEL, C1)
    "\u061c\u200e\u200f\u202a-\u202e\u2066-\u2069"  # bidirectional marks and overrides
    "\u2028\u2029"  # line and paragraph separators
    "\ud800-\udfff\ufffe\uffff]")  # lone surrogates and non-characters (invalid XML)


def _escape(match: re.Match[str]) -> str:
    code = ord(match.group())
    return f"\\x{code:02x}" if code < 0x100 else f"\\u{code:04x}"


def block(text: str) -> str:
    """``text`` with its lines kept (``\\r\\n`` read as a newline) and everything else escaped."""
    return _UNSAFE.sub(_escape, text.replace("\r\n", "\n"))


def line(text: str) -> str:
    """``text`` as one line: :func:`block`, with each newline shown as ``\\n``."""
    return block(text).replace("\n", "\\n")


def lines(text: str) -> list[str]:
    """The lines of ``text`` (as ``str.splitlines`` cuts at newlines only), each made safe."""
    parts = block(text).split("\n")
    return parts[:-1] if parts[-1] == "" else parts


def quoted(text: str, indent: str, *, last: int | None = None) -> list[str]:
    """The (``last``) lines of ``text`` behind ``indent`` and a ``| `` gutter.

    For a text report: output of a package's code stays visibly inside its quote, so no line
    of it can pass for a line of the report.
    """
    shown = lines(text)
    return [f"{indent}| {part}" for part in (shown[-last:] if last else shown)]
