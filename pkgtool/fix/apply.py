"""The ``lint --fix`` loop: lint, collect fixes, apply them, re-lint until nothing changes."""

from __future__ import annotations

import shutil
import tempfile
from collections.abc import Callable
from pathlib import Path

from pkgtool.edit.changes import Changes, FileChange, fix_changes, read_source
from pkgtool.edit.core import EditError, Fix
from pkgtool.findings import Finding
from pkgtool.fix.registry import Refusal, fixers
from pkgtool.model.files import list_files
from pkgtool.model.package import Package
from pkgtool.records import record, replace

ROUNDS = 50
"""Fixes deferred for overlapping an earlier one get this many more passes (ruff allows 100):
additions to one list of package.xml overlap, so a package missing a dozen dependencies takes
a round for each; the loop stops as soon as a round changes nothing."""

Check = Callable[[Path], tuple[Package, list[Finding]]]
"""Lint the package whose files are in the given folder (the package's own, or the copy
``--diff`` fixes) in the package's workspace."""


@record
class FixOutcome:
    """What fixing one package did: fixes applied, the diff (``--diff``), an error, the
    findings fixers left to the user (``CODE: why``) and the files written."""

    applied: tuple[str, ...] = ()
    diff: str = ""
    error: str | None = None
    refused: tuple[str, ...] = ()
    touched: tuple[str, ...] = ()


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
    """Fix the package at ``root``; with ``write`` False, fix a copy of its files in a
    temporary folder (``check`` reads them in the package's own workspace and repository),
    every round as ``--fix`` would, and give the diff from the package to the copy."""
    if write:
        return _fix_rounds(root, label, check, unsafe=unsafe)
    with tempfile.TemporaryDirectory(prefix="pkgtool-diff-") as folder:
        copy = Path(folder) / root.name  # as named as the package: rules may read it
        try:
            _copy_files(root, copy)
        except OSError as error:
            return FixOutcome(error=f"`{label}`: cannot copy the package to show its diff: "
                              f"{error}")
        outcome = _fix_rounds(copy, label, check, unsafe=unsafe)
        return replace(outcome, diff=_diff(root, copy, outcome.touched, label))


def _copy_files(root: Path, copy: Path) -> None:
    """Copy the files lint reads of the package at ``root`` (symbolic links followed as it
    follows them; no special files) into the folder ``copy``."""
    for relpath in list_files(root):
        target = copy / relpath
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(root / relpath, target)


def _fix_rounds(root: Path, label: str, check: Check, *, unsafe: bool) -> FixOutcome:
    """Lint, fix and write the package at ``root`` round after round until nothing changes."""
    applied: list[str] = []
    refused: list[str] = []
    touched: list[str] = []
    try:
        for _ in range(ROUNDS):
            package, findings = check(root)
            offered, refused = fixes_for(package, findings, unsafe=unsafe)
            changes, done, _deferred = fix_changes(root, offered, unsafe=unsafe)
            if not changes:
                break
            changes.write()
            applied.extend(f.title for f in done)
            touched.extend(changes.paths)
    except EditError as error:
        return FixOutcome(tuple(applied), error=f"`{label}`: {error}",
                          touched=tuple(dict.fromkeys(touched)))
    return FixOutcome(tuple(applied), refused=tuple(refused),
                      touched=tuple(dict.fromkeys(touched)))


def _diff(root: Path, copy: Path, paths: tuple[str, ...], label: str) -> str:
    """The unified diff from the files ``paths`` of the package at ``root`` to those of its
    fixed ``copy``."""
    files = []
    for path in sorted(paths):
        before, after = read_source(root, path), read_source(copy, path)
        if after is not None and (before is None or before.text != after.text):
            files.append(FileChange(path, before.text if before else None, after.text,
                                    after.encode(after.text)))
    return Changes(root, tuple(files)).diff(label)
