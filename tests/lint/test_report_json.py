"""JSON report: the contract. Renaming or removing a key is a schema_version bump."""

from __future__ import annotations

import json

from pkgtool import __version__
from pkgtool.report import PackageLabel, ReportContext, render
from pkgtool.report.json import SCHEMA_VERSION
from tests.helpers import make_finding

CONTEXT = ReportContext(packages=(PackageLabel("pkg", "src/pkg"), PackageLabel("b", "src/b")))


def test_document_keys_are_pinned() -> None:
    document = json.loads(render("json", [make_finding()], context=CONTEXT))
    assert list(document) == ["version", "schema_version", "findings", "summary"]
    assert document["version"] == __version__
    assert document["schema_version"] == SCHEMA_VERSION == 1
    assert list(document["findings"][0]) == ["rule", "severity", "package", "path", "line",
                                             "column", "message", "fix"]
    assert list(document["summary"]) == ["error", "warning", "info", "packages"]


def test_values() -> None:
    findings = [make_finding(), make_finding("MAN013", "warning", path="package.xml", line=0,
                                             col=0, fix=None)]
    document = json.loads(render("json", findings, context=CONTEXT))
    assert document["findings"] == [
        {"rule": "MAN013", "severity": "warning", "package": "pkg",
         "path": "src/pkg/package.xml", "line": None, "column": None,
         "message": "Python syntax error: invalid syntax", "fix": None},
        {"rule": "SYN001", "severity": "error", "package": "pkg", "path": "src/pkg/pkg/node.py",
         "line": 3, "column": 5, "message": "Python syntax error: invalid syntax",
         "fix": "Fix the syntax at the reported line and column"},
    ]
    assert document["summary"] == {"error": 1, "warning": 1, "info": 0, "packages": 2}


def test_empty() -> None:
    document = json.loads(render("json", [], context=ReportContext()))
    assert document["findings"] == []
    assert document["summary"] == {"error": 0, "warning": 0, "info": 0, "packages": 0}
