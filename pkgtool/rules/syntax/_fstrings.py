"""f-strings read with Python 3.12's rules (PEP 701), for a Python that predates them."""

from __future__ import annotations

import re
from pkgtool.lazy_regex import lazy_pattern

_OPENING = lazy_pattern(r"(?<![\w'\"])((?:[rR]?[fF]|[fF][rR]))('''|\"\"\"|'|\")")
_PREFIX = lazy_pattern(r"(?<!\w)[rRbBuUfF]{1,2}$")


def _string_end(text: str, i: int, quote: str, fmt: bool, nested: bool = False
                ) -> tuple[int, bool] | None:
    """(index after the closing quote, whether only 3.12 parses it) for the string whose body
    starts at ``i``; None when it never ends. A ``nested`` string (inside a replacement field)
    holding a backslash is 3.12's: older Pythons reject any backslash in a field."""
    newer = False
    while i < len(text):
        if text.startswith(quote, i):
            return i + len(quote), newer
        char = text[i]
        if char == "\\":
            newer = newer or nested
            i += 2
        elif char == "\n" and len(quote) == 1:
            return None
        elif fmt and text.startswith("{{", i):
            i += 2
        elif fmt and char == "{":
            field = _field_end(text, i + 1, quote)
            if field is None:
                return None
            i, field_newer = field
            newer = newer or field_newer
        else:
            i += 1
    return None


def _field_end(text: str, i: int, quote: str) -> tuple[int, bool] | None:
    """(index after the ``}`` closing a replacement field, whether only 3.12 parses it)."""
    depth, newer = 0, False
    while i < len(text):
        char = text[i]
        if char in "([{":
            depth += 1
        elif char in ")]}":
            if depth == 0:
                return (i + 1, newer) if char == "}" else None
            depth -= 1
        elif char == "\\" or char == "#" or (char == "\n" and len(quote) == 1):
            newer = True
            if char == "#":
                i = text.find("\n", i)
                if i < 0:
                    return None
                continue
        elif char in "'\"":
            prefix = _PREFIX.search(text, 0, i)
            inner = text[i:i + 3] if text[i:i + 3] in ("'''", '"""') else char
            end = _string_end(text, i + len(inner), inner,
                              prefix is not None and "f" in prefix.group().lower(), True)
            if end is None:
                return None
            newer = newer or end[1] or quote.startswith(inner) or inner.startswith(quote)
            i = end[0]
            continue
        i += 1
    return None


_BEFORE = 20
"""How many lines before the failing one an f-string that reaches it may open (a literal part
continued by a backslash at the end of its lines)."""


def needs_python_312(text: str, line: int) -> bool:
    """True when an f-string on ``line`` (1-based: opening there, or opening up to
    :data:`_BEFORE` lines earlier and reaching it) is complete under Python 3.12's rules but
    uses what older Pythons reject: its quote reused inside, a replacement field spanning
    lines, a backslash or a comment in one."""
    starts = [0] + [m.end() for m in re.finditer("\n", text)]
    if not 0 < line <= len(starts):
        return False
    stop = starts[line] if line < len(starts) else len(text)
    for opening in _OPENING.finditer(text, starts[max(line - 1 - _BEFORE, 0)], stop):
        end = _string_end(text, opening.end(), opening.group(2), True)
        if end is not None and end[1] and end[0] > starts[line - 1]:
            return True
    return False
