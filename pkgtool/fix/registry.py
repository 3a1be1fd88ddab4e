"""The fixer catalogue: which rule codes have a fix, whether it is safe, and the fixer itself."""

from __future__ import annotations

import importlib
from collections.abc import Callable, Iterable
from typing import TypeAlias

from pkgtool.edit.core import Fix
from pkgtool.findings import Finding
from pkgtool.model.package import Package
from pkgtool.records import record


@record
class Refusal:
    """A finding a fixer leaves to the user, and why (``lint --fix`` and ``--diff`` say it)."""

    reason: str


Make: TypeAlias = Callable[[Package, list[Finding]], Iterable["Fix | Refusal"]]

_MODULES = ("pkgtool.fix.data_files", "pkgtool.fix.dependencies", "pkgtool.fix.interfaces",
            "pkgtool.fix.launch",
            "pkgtool.fix.manifest", "pkgtool.fix.parameters", "pkgtool.fix.python",
            "pkgtool.fix.setup_cfg", "pkgtool.fix.setup_py")


@record
class Fixer:
    """How findings of ``code`` are repaired; ``safe`` fixes keep the package's behaviour."""

    code: str
    safe: bool
    title: str
    make: Make


_FIXERS: dict[str, Fixer] = {}


def fixer(code: str, title: str, *, safe: bool = True) -> Callable[[Make], Make]:
    """Register ``make`` as the fixer of rule ``code``."""

    def register(make: Make) -> Make:
        _FIXERS[code] = Fixer(code, safe, title, make)
        return make

    return register


def fixers() -> dict[str, Fixer]:
    """Every fixer, keyed by rule code."""
    for name in _MODULES:
        importlib.import_module(name)
    return dict(sorted(_FIXERS.items()))


def describe(code: str) -> str:
    """``safe fix``, ``unsafe fix`` or ``no fix``: what ``--list-rules`` and the docs show."""
    found = fixers().get(code)
    if found is None:
        return "no fix"
    return "safe fix" if found.safe else "unsafe fix (--unsafe-fixes)"
