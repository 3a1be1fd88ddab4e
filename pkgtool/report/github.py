"""GitHub Actions workflow commands: one ``::error``/``::warning``/``::notice`` per finding."""

from __future__ import annotations

from collections.abc import Sequence

from pkgtool.findings import Finding, Severity
from pkgtool.report import ReportContext, display_path
from pkgtool.report.untrusted import block

COMMANDS = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "notice"}


def _data(text: str) -> str:
    """Escape a command's message (GitHub's ``escapeData``) once it is made safe."""
    return block(text).replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A")


def _property(text: str) -> str:
    """Escape a property value (GitHub's ``escapeProperty``)."""
    return _data(text).replace(":", "%3A").replace(",", "%2C")


def annotation(finding: Finding) -> str:
    """``::error file=...,line=...,col=...,title=CODE::message`` for one finding."""
    properties = [f"file={_property(display_path(finding))}"]
    if finding.span.line:
        properties.append(f"line={finding.span.line}")
        if finding.span.col:
            properties.append(f"col={finding.span.col}")
    properties.append(f"title={_property(finding.code)}")
    message = finding.message + (f"\nhelp: {finding.fix}" if finding.fix else "")
    return f"::{COMMANDS[finding.severity]} {','.join(properties)}::{_data(message)}"


def render(findings: Sequence[Finding], *, context: ReportContext) -> str:
    """Every finding as an annotation line (nothing else: the log shows them as-is)."""
    del context  # annotations need nothing beyond the findings
    return "".join(annotation(f) + "\n" for f in findings)
