"""Reports: one writer per format for lint, test and grade, and lint's report in each format.

A format's module holds its one writer (:func:`pkgtool.report.junit.write`,
:func:`pkgtool.report.json.document`, :func:`pkgtool.report.csv.write`) and lint's pure
``render(findings, *, context) -> str``; test and grade map their results onto the same writers.
Text a package or a student controls passes through :mod:`pkgtool.report.untrusted`.
Renderers never read files or the environment; everything lint's need is in the
:class:`ReportContext` (the rule catalogue for rule metadata, the packages checked, colour).
"""

from __future__ import annotations

import importlib
from collections.abc import Mapping, Sequence

from pkgtool.findings import Finding, Severity
from pkgtool.model.span import Span
from pkgtool.records import field, record
from pkgtool.rules.registry import Rule

__all__ = ["FORMATS", "PackageLabel", "ReportContext", "counts", "display_path", "render",
           "sorted_findings"]

FORMATS = ("text", "json", "sarif", "github", "junit")
"""Output formats, each a module ``pkgtool.report.<format>``."""


@record
class PackageLabel:
    """A package that was checked: its name and its root as shown (relative to the cwd)."""

    name: str
    root: str


@record
class ReportContext:
    """What renderers know besides the findings."""

    packages: Sequence[PackageLabel] = ()
    rules: Mapping[str, Rule] = field(default_factory=dict)
    color: bool = False
    fixable: Mapping[str, bool] = field(default_factory=dict)
    """Rule codes ``lint --fix`` can repair, each mapped to whether the fix is safe."""


def fix_safety(finding: Finding, fixable: Mapping[str, bool]) -> bool | None:
    """Whether ``lint --fix`` repairs ``finding``: True (a safe fix), False (only with
    ``--unsafe-fixes``) or None (no fixer, or it makes no fix for this finding)."""
    if finding.manual or finding.code not in fixable:
        return None
    return fixable[finding.code] and not finding.unsafe_fix


def render(fmt: str, findings: Sequence[Finding], *, context: ReportContext) -> str:
    """Render ``findings`` in format ``fmt`` (one of :data:`FORMATS`)."""
    if fmt not in FORMATS:
        raise ValueError(f"unknown report format {fmt!r}")
    module = importlib.import_module(f"pkgtool.report.{fmt}")
    return str(module.render(sorted_findings(findings), context=context))


def display_path(finding: Finding, span: Span | None = None) -> str:
    """The finding's file (or ``span``'s, one of its related places) as the user sees it: the
    package root joined with the span path."""
    root, path = finding.root.rstrip("/"), (span or finding.span).path
    if not path:
        return root or "."
    return path if root in ("", ".") else f"{root}/{path}"


def sorted_findings(findings: Sequence[Finding]) -> list[Finding]:
    """Findings in report order: path, line, column, code."""
    return sorted(findings, key=lambda f: (display_path(f), f.span.line, f.span.col, f.code,
                                           f.message))


def counts(findings: Sequence[Finding]) -> dict[str, int]:
    """Number of findings per severity, every severity present."""
    result = {s.value: 0 for s in Severity}
    for finding in findings:
        result[finding.severity.value] += 1
    return result
