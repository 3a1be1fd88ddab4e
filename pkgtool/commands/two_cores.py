"""Check one package on two cores: a lint run of a single package (pre-commit's case) spends
most of its time importing the rules and running them, and both halves of the catalogue can
do that at once.

After the package is read, a forked child imports and runs the PYC rules (about half of the
time) while this process imports and runs the others; the two lists of findings are then
settled together exactly as :func:`pkgtool.engine.check_package` settles one. Whatever goes
wrong with the child, this process runs its rules too: the findings never depend on the split.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Optional

from pkgtool.commands.warm_worker import forked
from pkgtool.engine import Found, rule_findings, settled
from pkgtool.findings import Finding, Severity
from pkgtool.model.package import Package
from pkgtool.rules.registry import load

CHILD_FAMILY = "PYC"
"""The rules the child runs: the Python-code family, about half of a package's time."""


def check_on_two_cores(package: Package, codes: Sequence[str], *, root_label: str,
                       severities: Mapping[str, Severity]) -> Optional[list[Finding]]:
    """``check_package`` of the rules ``codes`` on ``package``, split between this process and
    a forked child; None where no child is used (then the caller checks as usual)."""
    theirs = [code for code in codes if code.startswith(CHILD_FAMILY)]
    mine = [code for code in codes if not code.startswith(CHILD_FAMILY)]

    def run(chosen: list[str]) -> list[Found]:
        return rule_findings(package, load(chosen).values(), root_label=root_label,
                             severities=severities)

    pending = forked(lambda: run(theirs)) if theirs and mine else None
    if pending is None:
        return None
    found = run(mine)
    answer = pending()
    found += answer if isinstance(answer, list) else run(theirs)
    return settled(sorted(found, key=lambda entry: entry[0].code))
