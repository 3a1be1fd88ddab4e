"""Run the selected rules over packages and turn hits into sorted, filtered findings."""

from __future__ import annotations

import ast
from collections.abc import Iterable, Mapping
from typing import Optional

from pkgtool.config import ALL, Layer, settings_for
from pkgtool.findings import Finding, Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.python_visitor import parse_tree
from pkgtool.model.span import Span
from pkgtool.model.static_branches import dead_expressions, dead_lines
from pkgtool.records import record, replace
from pkgtool.rules.registry import Rule


@record
class Selection:
    """Which rules run and at what severity, for callers without configuration files.

    ``select`` empty means every rule enabled by default; a selector is ``ALL``, a code, a
    family, a code prefix or a rule name (an unknown one raises
    :class:`pkgtool.config.ConfigError`). ``pkgtool lint`` layers configuration files (and
    per-rule severities) with :mod:`pkgtool.config` instead.
    """

    select: tuple[str, ...] = ()
    ignore: tuple[str, ...] = ()
    extend_select: tuple[str, ...] = ()

    def rules(self) -> list[Rule]:
        """The rules this selection runs, in code order."""
        layer = Layer("the selection", None, self.select or None, self.ignore,
                      self.extend_select)
        return list(settings_for([layer]).rules)


def _suppressed(package: Package, finding: Finding, rule: Rule) -> bool:
    """True when the finding's line silences every rule (bare, or ``ALL``) or this one."""
    codes = package.suppressions.get((finding.span.path, finding.span.line))
    if codes is None:
        return False
    return not codes or ALL in codes or rule.code in codes or rule.name in codes


Found = tuple[Finding, Optional[Hit]]
"""A finding and the hit it came from (None for a rule's internal error)."""


def check_package(package: Package, rules: Iterable[Rule], *, root_label: str,
                  severities: Mapping[str, Severity] | None = None) -> list[Finding]:
    """Run ``rules`` on one package; suppressed hits are dropped, the rest sorted.

    A rule that raises does not stop the run: its hits so far are dropped and it yields one
    error finding marked ``internal`` that names the rule and the exception.
    """
    return settled(rule_findings(package, rules, root_label=root_label, severities=severities))


def rule_findings(package: Package, rules: Iterable[Rule], *, root_label: str,
                  severities: Mapping[str, Severity] | None = None) -> list[Found]:
    """The findings of ``rules`` on ``package`` in rule order, unsuppressed, each with its hit:
    :func:`check_package` before :func:`settled` (rules may run in several processes)."""
    found: list[Found] = []
    overrides = severities or {}
    for rule in rules:
        try:
            hits = list(rule.check(package))
        except Exception as error:  # noqa: BLE001 - a broken rule must not hide the others
            found.append((_internal_error(package, rule, error, root_label), None))
            continue
        for hit in hits:
            if rule.code.startswith("PYC") and _never_runs(package, hit.span):
                continue
            finding = Finding(rule.code, overrides.get(rule.code, rule.severity), package.name,
                              root_label, hit.span, hit.message, hit.fix or rule.fix,
                              related=hit.related)
            if not _suppressed(package, finding, rule):
                found.append((finding, hit))
    return found


def settled(found: list[Found]) -> list[Finding]:
    """The findings of :func:`rule_findings` (of rules in code order), consequences folded
    into their causes, duplicates dropped, sorted."""
    return sorted(set(_fold_consequences(found)), key=lambda f: f.sort_key)


def _never_runs(package: Package, span: Span) -> bool:
    """True when ``span`` is on a line of Python code that never runs (after a ``return`` in
    its block, in an ``if`` branch never taken on Python 3: :func:`dead_lines`), or in a
    branch of a conditional expression never taken (:func:`dead_expressions`): the PYC
    rules judge what runs."""
    text = package.texts.get(span.path) if span.path.endswith(".py") and span.line else None
    tree = parse_tree(span.path, text) if text is not None else None
    where = (span.line, max(span.col - 1, 0))
    return isinstance(tree, ast.Module) and (
        any(first <= span.line <= last for first, last in dead_lines(tree)) or
        span.col > 0 and any(start <= where < end for start, end in dead_expressions(tree)))


def _fold_consequences(found: list[Found]) -> list[Finding]:
    """One finding per root cause: consequence hits join the finding that states their cause
    (its places in ``related``, named in its message, its severity the worst of them)."""
    causes = {hit.cause: finding for finding, hit in found
              if hit is not None and hit.cause and not hit.consequence}
    joined: dict[str, list[Finding]] = {}
    kept = []
    for finding, hit in found:
        if hit is not None and hit.consequence and hit.cause in causes:
            joined.setdefault(hit.cause, []).append(finding)
        else:
            kept.append(finding)
    for cause, parts in joined.items():
        stated = causes[cause]
        parts.sort(key=lambda f: f.sort_key)
        elsewhere = [f for f in parts if (f.span.path, f.span.line) !=
                     (stated.span.path, stated.span.line)]
        places = ", ".join(f"`{f.span.path}:{f.span.line}` ({f.code})" for f in elsewhere)
        worst = max((stated, *parts), key=lambda f: f.severity.rank).severity
        related = stated.related + tuple(span for f in elsewhere
                                         for span in (f.span, *f.related))
        joint = " The" if stated.message.endswith(("?", ".")) else "; the"
        kept[kept.index(stated)] = replace(
            stated, severity=worst, related=related,
            message=f"{stated.message}{joint} same mistake shows in {places}" if places
            else stated.message)
    return kept


def _internal_error(package: Package, rule: Rule, error: Exception, root_label: str) -> Finding:
    where = "package.xml" if package.has_file("package.xml") else ""
    message = (f"Internal error in rule `{rule.code}` (`{rule.name}`): "
               f"{type(error).__name__}: {error}")
    fix = f"Report this pkgtool bug; until it is fixed, skip the rule with `--ignore {rule.code}`"
    return Finding(rule.code, Severity.ERROR, package.name, root_label, Span(where), message,
                   fix, internal=True)
