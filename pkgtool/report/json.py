"""JSON: the one writer of lint, test and grade (and of SARIF and Gradescope), and lint's report.

pkgtool's own JSON documents share one schema (docs/json.md): the keys of :func:`document`,
then the command's own keys. Every string passes through :func:`pkgtool.report.untrusted.block`.
"""

from __future__ import annotations

import json
from collections.abc import Mapping, Sequence

from pkgtool import __version__
from pkgtool.findings import Finding
from pkgtool.report import ReportContext, counts, display_path, fix_safety
from pkgtool.report.untrusted import block

SCHEMA_VERSION = 1
"""Bumped when a key is renamed or removed (adding keys keeps the version)."""


def _safe(value: object) -> object:
    if isinstance(value, str):
        return block(value)
    if isinstance(value, Mapping):
        return {_safe(k): _safe(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_safe(v) for v in value]
    return value


def dumps(value: object) -> str:
    """``value`` as indented JSON, every string in it made safe."""
    return json.dumps(_safe(value), indent=2) + "\n"


def document(command: str, body: Mapping[str, object]) -> str:
    """A pkgtool JSON document: ``schema_version``, ``tool``, ``version``, ``command``, body."""
    return dumps({"schema_version": SCHEMA_VERSION, "tool": "pkgtool", "version": __version__,
                  "command": command, **body})


def finding_dict(finding: Finding, fixable: Mapping[str, bool]) -> dict[str, object]:
    """One finding as plain data; an unknown line or column (0) is null.

    ``fixable`` (rule code -> safe) gives the ``fixable`` key: whether ``lint --fix`` repairs
    it, ``safe``, ``unsafe`` (only with ``--unsafe-fixes``) or null. ``related`` lists the
    other places of the same mistake.
    """
    safe = fix_safety(finding, fixable)
    return {
        "rule": finding.code,
        "severity": finding.severity.value,
        "package": finding.package,
        "path": display_path(finding),
        "line": finding.span.line or None,
        "column": finding.span.col or None,
        "message": finding.message,
        "fix": finding.fix,
        "fixable": None if safe is None else "safe" if safe else "unsafe",
        "related": [{"path": display_path(finding, span), "line": span.line or None,
                     "column": span.col or None} for span in finding.related],
    }


def render(findings: Sequence[Finding], *, context: ReportContext) -> str:
    """lint's findings and a summary of them."""
    return document("lint", {"findings": [finding_dict(f, context.fixable)
                                          for f in findings],
                             "summary": {**counts(findings), "packages": len(context.packages)}})
