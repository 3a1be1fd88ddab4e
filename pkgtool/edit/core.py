"""Edits and fixes: what an editor or a rule proposes, conflict detection, and splicing.

Offsets index a file's decoded text after its byte-order mark (see :mod:`pkgtool.edit.source`).
A new file is one edit with ``create=True`` that inserts its whole text at offset 0.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence

from pkgtool.records import record


class EditError(Exception):
    """An edit pkgtool refuses to make; the message says why and what to do instead."""


@record(order=True)
class Edit:
    """Replace ``text[start:end]`` of the file at ``path`` (package-relative POSIX)."""

    path: str
    start: int
    end: int
    replacement: str
    create: bool = False
    """The file does not exist yet; the edit is its whole content."""

    def __post_init__(self) -> None:
        if not 0 <= self.start <= self.end:
            raise ValueError(f"bad span {self.start}..{self.end} in {self.path}")

    def overlaps(self, other: Edit) -> bool:
        """True when the two edits cannot both apply in a well-defined way."""
        if self.path != other.path or self == other:
            return False
        if self.create or other.create:
            return True
        if self.start == self.end == other.start == other.end:
            return True  # two insertions at one point: their order would be a guess
        return self.start < other.end and other.start < self.end or \
            (self.start == self.end and other.start < self.start < other.end) or \
            (other.start == other.end and self.start < other.start < self.end)


@record
class Fix:
    """A titled group of edits applied together or not at all (what a rule can return).

    ``safe`` fixes keep the package's behaviour; unsafe ones (removing a dependency, say)
    apply only when the user asks for them.
    """

    title: str
    edits: tuple[Edit, ...]
    safe: bool = True

    @property
    def paths(self) -> tuple[str, ...]:
        """The files this fix touches, sorted."""
        return tuple(sorted({edit.path for edit in self.edits}))


def conflicts(edits: Iterable[Edit]) -> list[tuple[Edit, Edit]]:
    """Every pair of distinct edits that overlap (identical edits are not a conflict)."""
    ordered = sorted(set(edits))
    found = []
    for index, first in enumerate(ordered):
        for second in ordered[index + 1:]:
            if second.path != first.path or second.start > first.end:
                break
            if first.overlaps(second):
                found.append((first, second))
    return found


def select_fixes(fixes: Sequence[Fix]) -> tuple[list[Fix], list[Fix]]:
    """(chosen, deferred): fixes in order, skipping any that conflicts with one chosen before.

    A caller applies the chosen ones, re-reads the files and asks again for the deferred.
    """
    chosen: list[Fix] = []
    taken: list[Edit] = []
    deferred: list[Fix] = []
    for fix in fixes:
        if conflicts(fix.edits) or any(a.overlaps(b) for a in fix.edits for b in taken):
            deferred.append(fix)
        else:
            chosen.append(fix)
            taken.extend(fix.edits)
    return chosen, deferred


def apply_edits(text: str, edits: Iterable[Edit]) -> str:
    """``text`` with ``edits`` (all of one file) spliced in; overlapping edits raise EditError."""
    unique = sorted(set(edits), key=lambda e: (e.start, e.end))
    clash = conflicts(unique)
    if clash:
        first, second = clash[0]
        raise EditError(f"Two edits of `{first.path}` overlap ({first.start}..{first.end} and "
                        f"{second.start}..{second.end}); apply them one after the other.")
    pieces = []
    at = 0
    for edit in unique:
        if edit.end > len(text):
            raise EditError(f"An edit of `{edit.path}` reaches past its end; re-read the file.")
        pieces += [text[at:edit.start], edit.replacement]
        at = edit.end
    pieces.append(text[at:])
    return "".join(pieces)
