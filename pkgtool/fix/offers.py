"""Which findings ``lint --fix`` repairs: a finding is offered as fixable only when its rule's
fixer makes a fix for it.

A rule cannot always tell whether its fixer will manage (an undefined name with no module to
import it from, an entry point whose function is found nowhere): rather than repeat each
fixer's conditions in its rule, the fixer itself is asked, finding by finding, once the rules
have run. A finding it makes no fix for (it refuses, offers nothing or fails) is marked
``manual``, and reports do not mark it fixable. Fixers only plan edits: nothing is written.
"""

from __future__ import annotations

from pkgtool.edit.core import Fix
from pkgtool.findings import Finding
from pkgtool.fix.registry import Fixer, fixers
from pkgtool.model.package import Package
from pkgtool.records import replace
from pkgtool.rules._index import FIXED


def offers_marked(package: Package, findings: list[Finding]) -> list[Finding]:
    """``findings`` in order, those their fixer makes no fix for marked ``manual``."""
    if not any(_candidate(f) for f in findings):
        return findings
    table = fixers()
    return [replace(finding, manual=True) if _candidate(finding) and
            not _offered(table[finding.code], package, finding) else finding
            for finding in findings]


def _candidate(finding: Finding) -> bool:
    """A finding a fixer may repair (the fixers are imported only when there is one)."""
    return finding.code in FIXED and not finding.manual and not finding.internal


def _offered(fixer: Fixer, package: Package, finding: Finding) -> bool:
    """True when ``fixer`` makes at least one fix for ``finding`` alone."""
    try:
        return any(isinstance(offer, Fix) for offer in fixer.make(package, [finding]))
    except Exception:  # noqa: BLE001 - a fixer that fails on this package offers nothing
        return False
