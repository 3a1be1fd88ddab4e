"""Seeded mistakes: one typical student mistake inserted into a correct package, per case.

A case is a function that mutates a copy of a correct package in place, registered with
:func:`case` under the rule code lint must report, and where: the file and a piece of text
on the reported line (the first line of the mutated file that contains it).
"""

from __future__ import annotations

import textwrap
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

CREATED = "created"
"""The package ``pkgtool create base_pkg --node talker:publisher --node listener:subscriber
--node srv:service --launch --config`` writes; other bases are reference package names."""

Mutation = Callable[[Path], None]


@dataclass(frozen=True, slots=True)
class Case:
    """One seeded mistake and the finding lint must give for it."""

    id: str
    mutate: Mutation
    code: str
    path: str | None
    at: str | None
    base: str


CASES: list[Case] = []


def case(code: str, path: str | None = None, at: str | None = None, *,
         base: str = CREATED) -> Callable[[Mutation], Mutation]:
    """Register the decorated mutation: lint must report ``code`` in ``path`` on the line
    holding ``at`` (any line when ``at`` is None, any file when ``path`` is None)."""

    def register(mutate: Mutation) -> Mutation:
        CASES.append(Case(mutate.__name__, mutate, code, path, at, base))
        return mutate

    return register


def edit(root: Path, relpath: str, old: str, new: str) -> None:
    """Replace the first ``old`` in a file by ``new``; ``old`` must be there. Deleting all a
    line held deletes the line, as a person would (no whitespace-only line is left)."""
    path = root / relpath
    text = path.read_text()
    assert old in text, f"{old!r} not in {relpath}"
    at = text.index(old)
    text = text[:at] + new + text[at + len(old):]
    start, end = text.rfind("\n", 0, at) + 1, text.find("\n", at)
    if not new and not old.endswith("\n") and end >= 0 and not text[start:end].strip():
        text = text[:start] + text[end + 1:]
    path.write_text(text)


def add_import(root: Path, relpath: str, statement: str) -> None:
    """Put an import among the third-party imports around ``import rclpy``, in the order
    ament's flake8 (import-order, google style) wants: by module name, case-insensitively."""
    path = root / relpath
    lines = path.read_text().splitlines(keepends=True)
    at = lines.index("import rclpy\n")
    start, end = at, at
    while start > 0 and lines[start - 1].startswith(("import ", "from ")):
        start -= 1
    while end + 1 < len(lines) and lines[end + 1].startswith(("import ", "from ")):
        end += 1

    def module(line: str) -> str:
        return line.split()[1].lower()

    place = next((i for i in range(start, end + 1)
                  if module(lines[i]) > module(statement)), end + 1)
    lines.insert(place, statement + "\n")
    path.write_text("".join(lines))


def header(root: Path) -> str:
    """The package's license header (the leading comment block of its setup.py), which a
    person copies into a file they add."""
    kept = []
    for line in (root / "setup.py").read_text().splitlines(keepends=True):
        if not line.startswith("#"):
            break
        kept.append(line)
    return "".join(kept) + ("\n" if kept else "")


def write(root: Path, relpath: str, text: str, *, licensed: bool = False) -> None:
    """Write a (dedented) file, creating its folders; ``licensed`` puts the package's
    license header first."""
    path = root / relpath
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text((header(root) if licensed else "") + textwrap.dedent(text).lstrip("\n"))


def move(root: Path, source: str, destination: str) -> None:
    """Move a file inside the package, creating the destination's folders."""
    (root / destination).parent.mkdir(parents=True, exist_ok=True)
    (root / source).rename(root / destination)


def remove(root: Path, relpath: str) -> None:
    """Delete a file of the package."""
    (root / relpath).unlink()
