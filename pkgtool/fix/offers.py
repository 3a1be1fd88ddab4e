"""Which findings ``lint --fix`` repairs: a finding is offered as fixable only when its rule's
fixer makes a fix for it.

A rule cannot always tell whether its fixer will manage (an undefined name with no module to
import it from, an entry point whose function is found nowhere): rather than repeat each
fixer's conditions in its rule, the fixer itself is asked, finding by finding, once the rules
have run. A finding it makes no fix for (it refuses, offers nothing or fails) is marked
``manual``, and reports do not mark it fixable. Fixers only plan edits: nothing is written.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from pkgtool.findings import Finding
from pkgtool.records import replace
from pkgtool.rules._index import FIXED

if TYPE_CHECKING:
    from pkgtool.edit.core import Fix
    from pkgtool.fix.registry import Fixer
    from pkgtool.model.package import Package


def offers_marked(package: Package, findings: list[Finding]) -> list[Finding]:
    """``findings`` in order, those their fixer makes no fix for marked ``manual``, those it
    makes only unsafe fixes for (a fixer whose other fixes are safe) ``unsafe_fix``."""
    if not any(_candidate(f) for f in findings):
        return findings
    from pkgtool.fix.registry import fixers  # only here: a clean package needs no fixer

    table = fixers()
    return [_marked(finding, _offered(table[finding.code], package, finding))
            if _candidate(finding) else finding for finding in findings]


def _marked(finding: Finding, offered: list[Fix]) -> Finding:
    if not offered:
        return replace(finding, manual=True)
    return replace(finding, unsafe_fix=True) if not any(f.safe for f in offered) else finding


def _candidate(finding: Finding) -> bool:
    """A finding a fixer may repair (the fixers are imported only when there is one)."""
    return finding.code in FIXED and not finding.manual and not finding.internal


def _offered(fixer: Fixer, package: Package, finding: Finding) -> list[Fix]:
    """The fixes ``fixer`` makes for ``finding`` alone."""
    try:
        from pkgtool.edit.core import Fix

        return [offer for offer in fixer.make(package, [finding]) if isinstance(offer, Fix)]
    except Exception:  # noqa: BLE001 - a fixer that fails on this package offers nothing
        return []
