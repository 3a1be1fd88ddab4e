"""Machine output: a versioned JSON document whose keys a contract test pins."""

from __future__ import annotations

import json
from collections.abc import Sequence

from pkgtool import __version__
from pkgtool.findings import Finding
from pkgtool.report import ReportContext, counts, display_path

SCHEMA_VERSION = 1
"""Bumped when a key is renamed or removed (adding keys keeps the version)."""


def finding_dict(finding: Finding) -> dict[str, object]:
    """One finding as plain data; an unknown line or column (0) is null."""
    return {
        "rule": finding.code,
        "severity": finding.severity.value,
        "package": finding.package,
        "path": display_path(finding),
        "line": finding.span.line or None,
        "column": finding.span.col or None,
        "message": finding.message,
        "fix": finding.fix,
    }


def render(findings: Sequence[Finding], *, context: ReportContext) -> str:
    """``{"version", "schema_version", "findings", "summary"}`` as indented JSON."""
    document = {
        "version": __version__,
        "schema_version": SCHEMA_VERSION,
        "findings": [finding_dict(f) for f in findings],
        "summary": {**counts(findings), "packages": len(context.packages)},
    }
    return json.dumps(document, indent=2) + "\n"
