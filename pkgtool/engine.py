"""Run the selected rules over packages and turn hits into sorted, filtered findings."""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field

from pkgtool.findings import Finding, Severity
from pkgtool.model.package import ALL, Package
from pkgtool.rules.registry import Rule, load_all, resolve


@dataclass(frozen=True, slots=True)
class Selection:
    """Which rules run and at what severity (from the CLI and ``[tool.pkgtool]``).

    ``select`` empty means every rule enabled by default; a selector is a code, a family prefix
    or a rule name. ``severities`` overrides a rule's severity by code.
    """

    select: tuple[str, ...] = ()
    ignore: tuple[str, ...] = ()
    extend_select: tuple[str, ...] = ()
    severities: Mapping[str, Severity] = field(default_factory=dict)

    def rules(self) -> list[Rule]:
        """The rules this selection runs, in code order."""
        catalogue = load_all()
        if self.select:
            chosen = {r.code: r for s in self.select for r in resolve(s)}
        else:
            chosen = {c: r for c, r in catalogue.items() if r.default_enabled}
        chosen.update({r.code: r for s in self.extend_select for r in resolve(s)})
        for selector in self.ignore:
            for ignored in resolve(selector):
                chosen.pop(ignored.code, None)
        return [chosen[c] for c in sorted(chosen)]


def _suppressed(package: Package, finding: Finding, rule: Rule) -> bool:
    codes = package.suppressions.get((finding.span.path, finding.span.line))
    return bool(codes) and (ALL in codes or rule.code in codes or rule.name in codes)


def check_package(package: Package, rules: Iterable[Rule], *, root_label: str,
                  severities: Mapping[str, Severity] | None = None) -> list[Finding]:
    """Run ``rules`` on one package; suppressed hits are dropped, the rest sorted."""
    findings = []
    overrides = severities or {}
    for rule in rules:
        for hit in rule.check(package):
            finding = Finding(rule.code, overrides.get(rule.code, rule.severity), package.name,
                              root_label, hit.span, hit.message, hit.fix or rule.fix)
            if not _suppressed(package, finding, rule):
                findings.append(finding)
    return sorted(set(findings), key=lambda f: f.sort_key)
