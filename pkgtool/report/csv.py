"""CSV: the one writer of tables for spreadsheets (grade's gradebook).

Text cells pass through :func:`pkgtool.report.untrusted.line` (one row per line), and a text
cell that a spreadsheet could read as a formula or command is neutralised with a leading ``'``.
"""

from __future__ import annotations

import csv
import io
from collections.abc import Iterable, Sequence

from pkgtool.report.untrusted import line

FORMULA_STARTS = ("=", "+", "-", "@")
"""What spreadsheets run as a formula at the start of a cell (after any blanks)."""


def cell(value: object) -> object:
    """A text cell made safe (``'`` before a formula or a leading blank); numbers as they are."""
    if not isinstance(value, str):
        return value
    text = line(value)
    if text[:1].isspace() or text.lstrip().startswith(FORMULA_STARTS):
        return "'" + text
    return text


def write(header: Sequence[str], rows: Iterable[Sequence[object]]) -> str:
    """The table as CSV, a header line then one line per row."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow([cell(h) for h in header])
    writer.writerows([cell(v) for v in row] for row in rows)
    return buffer.getvalue()
