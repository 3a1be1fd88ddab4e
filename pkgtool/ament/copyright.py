"""Find the copyright notice and license of a source file as ament_copyright does.

ament_copyright reads every block of ``#`` comment lines of a file (after a shebang or coding
line) and wants a ``Copyright <years> <holder>`` line plus a known license header in the same
block. pkgtool also accepts an ``SPDX-License-Identifier:`` line as the license.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from pkgtool.knowledge.licenses import license_of_header, spdx_in_text

_YEARS = r"\d{4}(?:\s*-\s*\d{4})?(?:,\s*\d{4}(?:\s*-\s*\d{4})?)*"
COPYRIGHT_LINE = re.compile(  # ament_copyright's pattern: one stray character may lead
    rf"^.?\s*(?:\\copyright\s*)?copyright(?:\s+\(c\))?\s+({_YEARS}),?\s+(\S.*)$", re.IGNORECASE)


@dataclass(frozen=True, slots=True)
class Header:
    """What a file's comment blocks say: copyright line number, license (SPDX id) and its line."""

    copyright_line: int | None
    license: str | None
    license_line: int | None


def _comment_blocks(text: str) -> list[tuple[int, list[str]]]:
    """Runs of consecutive ``#`` comment lines as (first line number, stripped texts)."""
    blocks: list[tuple[int, list[str]]] = []
    current: list[str] = []
    start = 0
    for number, line in enumerate(text.splitlines(), 1):
        stripped = line.lstrip()
        is_comment = stripped.startswith("#") and not (number == 1 and stripped.startswith("#!"))
        if is_comment:
            if not current:
                start = number
            current.append(stripped[1:].strip())
        elif current:
            blocks.append((start, current))
            current = []
    if current:
        blocks.append((start, current))
    return blocks


def read_header(text: str) -> Header:
    """The first copyright notice and the first license found in the comment blocks."""
    copyright_line = license_ = license_line = None
    for start, lines in _comment_blocks(text):
        for offset, line in enumerate(lines):
            if copyright_line is None and COPYRIGHT_LINE.match(line):
                copyright_line = start + offset
            if license_ is None and spdx_in_text(line):
                license_, license_line = spdx_in_text(line), start + offset
        if license_ is None and license_of_header("\n".join(lines)):
            license_, license_line = license_of_header("\n".join(lines)), start
    return Header(copyright_line, license_, license_line)
