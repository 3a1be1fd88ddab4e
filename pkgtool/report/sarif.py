"""SARIF 2.1.0 for code-scanning services, with each rule's metadata from the registry.

Written by :func:`pkgtool.report.json.dumps`: every string is made safe.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import PurePosixPath
from urllib.parse import quote

from pkgtool import __version__
from pkgtool.findings import Finding, Severity
from pkgtool.model.span import Span
from pkgtool.report import ReportContext, display_path, fix_safety
from pkgtool.report.json import dumps
from pkgtool.rules.registry import FAMILIES, Rule

SCHEMA = "https://json.schemastore.org/sarif-2.1.0.json"
LEVELS = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "note"}


def rule_descriptor(rule: Rule) -> dict[str, object]:
    """A ``reportingDescriptor``: id, name, descriptions, help and default level."""
    return {
        "id": rule.code,
        "name": rule.name,
        "shortDescription": {"text": rule.summary},
        "fullDescription": {"text": _description(rule.doc)},
        "help": {"text": rule.doc, "markdown": rule.doc},
        "defaultConfiguration": {"level": LEVELS[rule.severity],
                                 "enabled": rule.default_enabled},
        "properties": {"tags": [rule.family, FAMILIES.get(rule.family, "")]},
    }


def _description(doc: str) -> str:
    """The first paragraph of the ``## What it does`` section, else the summary line."""
    _, _, rest = doc.partition("## What it does")
    paragraph = rest.strip().split("\n\n", 1)[0].strip()
    return " ".join(paragraph.split()) or doc.strip().split("\n", 1)[0]


def _uri(path: str) -> dict[str, str]:
    if PurePosixPath(path).is_absolute():
        return {"uri": "file://" + quote(path)}
    return {"uri": quote(path), "uriBaseId": "%SRCROOT%"}


def _location(finding: Finding, span: Span) -> dict[str, object]:
    region = {"startLine": span.line} if span.line else {}
    if region and span.col:
        region["startColumn"] = span.col
    location: dict[str, object] = {"artifactLocation": _uri(display_path(finding, span))}
    if region:
        location["region"] = region
    return location


def _result(finding: Finding, index: dict[str, int], fixable: Mapping[str, bool]
            ) -> dict[str, object]:
    location = _location(finding, finding.span)
    properties = {"package": finding.package}
    safe = fix_safety(finding, fixable)
    if safe is not None:
        properties["fixable"] = "safe" if safe else "unsafe"
    result: dict[str, object] = {
        "ruleId": finding.code,
        "level": LEVELS[finding.severity],
        "message": {"text": f"{finding.message}. Fix: {finding.fix}" if finding.fix
                    else finding.message},
        "locations": [{"physicalLocation": location}],
        "properties": properties,
    }
    if finding.related:
        result["relatedLocations"] = [{"id": number, "physicalLocation": _location(finding, span)}
                                      for number, span in enumerate(finding.related, 1)]
    if finding.code in index:
        result["ruleIndex"] = index[finding.code]
    return result


def render(findings: Sequence[Finding], *, context: ReportContext) -> str:
    """One SARIF run listing every known rule and a result per finding."""
    rules = [context.rules[code] for code in sorted(context.rules)]
    index = {rule.code: i for i, rule in enumerate(rules)}
    run = {
        "tool": {"driver": {
            "name": "pkgtool",
            "version": __version__,
            "semanticVersion": __version__,
            "rules": [rule_descriptor(rule) for rule in rules],
        }},
        "originalUriBaseIds": {"%SRCROOT%": {"description": {
            "text": "The folder pkgtool lint ran in"}}},
        "results": [_result(f, index, context.fixable) for f in findings],
    }
    return dumps({"$schema": SCHEMA, "version": "2.1.0", "runs": [run]})
