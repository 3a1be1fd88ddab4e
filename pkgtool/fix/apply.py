"""The ``lint --fix`` loop: lint, collect fixes, apply them, re-lint until nothing changes."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from pkgtool.edit.changes import fix_changes
from pkgtool.edit.core import EditError, Fix
from pkgtool.findings import Finding
from pkgtool.fix.registry import Refusal, fixers
from pkgtool.model.package import Package
from pkgtool.records import record

ROUNDS = 50
"""Fixes deferred for overlapping an earlier one get this many more passes (ruff allows 100):
additions to one list of package.xml overlap, so a package missing a dozen dependencies takes
a round for each; the loop stops as soon as a round changes nothing."""

Check = Callable[[Path], tuple[Package, list[Finding]]]


@record
class FixOutcome:
    """What fixing one package did: fixes applied, the diff (``--diff``), an error, and the
    findings fixers left to the user (``CODE: why``)."""

    applied: tuple[str, ...] = ()
    diff: str = ""
    error: str | None = None
    refused: tuple[str, ...] = ()


def fixes_for(package: Package, findings: list[Finding], *, unsafe: bool
              ) -> tuple[list[Fix], list[str]]:
    """The fixes the registered fixers offer for ``findings`` (safe only unless ``unsafe``),
    and their refusals as ``CODE: why``."""
    found: list[Fix] = []
    refused: list[str] = []
    for code, entry in fixers().items():
        mine = [f for f in findings if f.code == code and not f.internal]
        if mine and (entry.safe or unsafe):
            for offer in entry.make(package, mine):
                if isinstance(offer, Refusal):
                    refused.append(f"{code}: {offer.reason}")
                else:
                    found.append(offer)
    return found, list(dict.fromkeys(refused))


def fix_package(root: Path, label: str, check: Check, *, unsafe: bool, write: bool
                ) -> FixOutcome:
    """Fix the package at ``root``; with ``write`` False, only the first round's diff."""
    applied: list[str] = []
    refused: list[str] = []
    try:
        for _ in range(ROUNDS):
            package, findings = check(root)
            offered, refused = fixes_for(package, findings, unsafe=unsafe)
            changes, done, _deferred = fix_changes(root, offered, unsafe=unsafe)
            if not changes:
                break
            if not write:
                return FixOutcome(tuple(f.title for f in done), changes.diff(label),
                                  refused=tuple(refused))
            changes.write()
            applied.extend(f.title for f in done)
    except EditError as error:
        return FixOutcome(tuple(applied), error=f"`{label}`: {error}")
    return FixOutcome(tuple(applied), refused=tuple(refused))
