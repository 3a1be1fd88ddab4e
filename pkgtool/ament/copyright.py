"""Find the copyright notice and license of a source file as ament_copyright does.

ament_copyright reads the first block of ``#`` comment lines of a file (those starting in the
first column, after a shebang or coding line) and wants a ``Copyright <years> <holder>`` line
plus a known license header in that block. pkgtool also accepts an ``SPDX-License-Identifier:``
line as the license, and recognises a header by its key phrases (ament wants the whole text).
"""

from __future__ import annotations

import re

from pkgtool.knowledge.licenses import license_of_header, spdx_in_text
from pkgtool.records import record
from pkgtool.lazy_regex import lazy_pattern

_YEARS = r"\d{4}(?:\s*-\s*\d{4})?(?:,\s*\d{4}(?:\s*-\s*\d{4})?)*"
COPYRIGHT_LINE = lazy_pattern(  # ament_copyright's pattern: one stray character may lead
    rf"^.?\s*(?:\\copyright\s*)?copyright(?:\s+\(c\))?\s+({_YEARS}),?\s+(\S.*)$", re.IGNORECASE)


@record
class Header:
    """What a file's comment blocks say: copyright line number, license (SPDX id) and its line."""

    copyright_line: int | None
    license: str | None
    license_line: int | None


def _first_comment_block(text: str) -> tuple[int, list[str]]:
    """ament_copyright's block: the first run of ``#`` lines, after shebang and coding lines.

    Returns (first line number, texts without the ``#`` and surrounding blanks); (0, []) when
    the file has no comment line.
    """
    lines = text.splitlines()
    start = 0
    while start < len(lines) and lines[start].startswith("#") and (
            lines[start].startswith("#!") or "coding=" in lines[start]
            or "coding:" in lines[start]):
        start += 1
    first = next((n for n in range(start, len(lines)) if lines[n].startswith("#")), None)
    if first is None:
        return 0, []
    block = []
    for line in lines[first:]:
        if not line.startswith("#"):
            break
        block.append(line[1:].strip())
    return first + 1, block


def read_header(text: str) -> Header:
    """The copyright notice and the license found in the first comment block."""
    start, lines = _first_comment_block(text)
    copyright_line = license_ = license_line = None
    for offset, line in enumerate(lines):
        if copyright_line is None and COPYRIGHT_LINE.match(line):
            copyright_line = start + offset
        if license_ is None and spdx_in_text(line):
            license_, license_line = spdx_in_text(line), start + offset
    if license_ is None and license_of_header("\n".join(lines)):
        license_, license_line = license_of_header("\n".join(lines)), start
    return Header(copyright_line, license_, license_line)
