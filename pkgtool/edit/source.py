"""A file's text as editors see it: decoded, byte-order mark set aside, newline style known.

Python files are decoded with their PEP 263 coding declaration; every other file is UTF-8.
Encoding the edited text back gives the original bytes wherever the text did not change.
"""

from __future__ import annotations

import codecs
from bisect import bisect_right
from dataclasses import dataclass
from functools import cached_property

from pkgtool.edit.core import EditError
from pkgtool.lazy_regex import lazy_pattern

MAX_BYTES = 2 * 1024 * 1024
"""Larger files are not edited (the model does not read them either)."""
_CODING = lazy_pattern(rb"^[ \t\f]*#.*?coding[:=][ \t]*([-\w.]+)")
_LINE_BREAK = lazy_pattern(r"\r\n|\r|\n")


@dataclass(frozen=True)
class Source:
    """The decoded ``text`` of ``path`` (without BOM), and how to turn it back into bytes."""

    path: str
    text: str
    encoding: str = "utf-8"
    bom: bool = False

    @classmethod
    def from_bytes(cls, path: str, data: bytes) -> Source:
        """Decode ``data``; binary, oversized or undecodable content raises EditError."""
        if len(data) > MAX_BYTES or b"\0" in data:
            raise EditError(f"`{path}` is binary or larger than {MAX_BYTES} bytes: pkgtool does "
                            "not edit it. Make the change by hand.")
        bom = data.startswith(codecs.BOM_UTF8)
        body = data[len(codecs.BOM_UTF8):] if bom else data
        encoding = _python_encoding(body) if path.endswith(".py") and not bom else "utf-8"
        try:
            text = body.decode(encoding)
        except (UnicodeDecodeError, LookupError):
            raise EditError(f"`{path}` is not valid {encoding}: pkgtool does not edit it. "
                            "Fix its encoding first.") from None
        return cls(path, text, encoding, bom)

    def encode(self, text: str) -> bytes:
        """``text`` (an edited version of this file) as the file's bytes."""
        try:
            data = text.encode(self.encoding)
        except UnicodeEncodeError:
            raise EditError(f"The change to `{self.path}` has characters its encoding "
                            f"({self.encoding}) cannot hold; make it by hand.") from None
        return codecs.BOM_UTF8 + data if self.bom else data

    @cached_property
    def newline(self) -> str:
        """The file's line break: its first one, else ``\\n``."""
        found = _LINE_BREAK.search(self.text)
        return found.group() if found else "\n"

    @cached_property
    def line_starts(self) -> list[int]:
        """Offset of the first character of each line (index 0 is line 1)."""
        return [0] + [m.end() for m in _LINE_BREAK.finditer(self.text)]

    def offset_of_utf8(self, line: int, byte_column: int) -> int:
        """Character offset of ``ast``'s position (1-based line, column in UTF-8 bytes)."""
        start = self.line_starts[line - 1]
        end = self.line_end(start)
        prefix = self.text[start:end].encode("utf-8")[:byte_column]
        return start + len(prefix.decode("utf-8", errors="ignore"))

    def line_end(self, offset: int) -> int:
        """Offset of the line break ending the line that holds ``offset`` (or the text end)."""
        found = _LINE_BREAK.search(self.text, offset)
        return found.start() if found else len(self.text)

    def line_start(self, offset: int) -> int:
        """Offset of the first character of the line that holds ``offset``."""
        return self.line_starts[bisect_right(self.line_starts, offset) - 1]

    def indent_at(self, offset: int) -> str | None:
        """The whitespace before ``offset`` on its line, or None if other text precedes it."""
        before = self.text[self.line_start(offset):offset]
        return before if not before.strip() else None


def _python_encoding(data: bytes) -> str:
    """The PEP 263 declaration of the first two lines, else UTF-8."""
    for line in data.split(b"\n", 2)[:2]:
        match = _CODING.match(line)
        if match:
            name = match.group(1).decode("ascii", errors="replace")
            try:
                return codecs.lookup(name).name
            except LookupError:
                return name
        if line.strip() and not line.lstrip().startswith(b"#"):
            break
    return "utf-8"
