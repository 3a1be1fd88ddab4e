"""The ``lint --fix`` loop: lint, collect fixes, apply them, re-lint until nothing changes."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from pkgtool.edit.changes import fix_changes
from pkgtool.edit.core import EditError, Fix
from pkgtool.findings import Finding
from pkgtool.fix.registry import fixers
from pkgtool.model.package import Package

ROUNDS = 8
"""Fixes deferred for overlapping an earlier one get this many more passes."""

Check = Callable[[Path], tuple[Package, list[Finding]]]


@dataclass(frozen=True, slots=True)
class FixOutcome:
    """What fixing one package did: fixes applied, the diff (``--diff``), and a refusal."""

    applied: tuple[str, ...] = ()
    diff: str = ""
    error: str | None = None


def fixes_for(package: Package, findings: list[Finding], *, unsafe: bool) -> list[Fix]:
    """The fixes the registered fixers offer for ``findings`` (safe only unless ``unsafe``)."""
    found: list[Fix] = []
    for code, entry in fixers().items():
        mine = [f for f in findings if f.code == code and not f.internal]
        if mine and (entry.safe or unsafe):
            found.extend(entry.make(package, mine))
    return found


def fix_package(root: Path, label: str, check: Check, *, unsafe: bool, write: bool
                ) -> FixOutcome:
    """Fix the package at ``root``; with ``write`` False, only the first round's diff."""
    applied: list[str] = []
    try:
        for _ in range(ROUNDS):
            package, findings = check(root)
            changes, done, _deferred = fix_changes(
                root, fixes_for(package, findings, unsafe=unsafe), unsafe=unsafe)
            if not changes:
                break
            if not write:
                return FixOutcome(tuple(f.title for f in done), changes.diff(label))
            changes.write()
            applied.extend(f.title for f in done)
    except EditError as error:
        return FixOutcome(tuple(applied), error=f"`{label}`: {error}")
    return FixOutcome(tuple(applied))
