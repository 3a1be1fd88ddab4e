"""JSON report of lint: the values (tests/test_json_contract.py pins the keys)."""

from __future__ import annotations

import json

from pkgtool.report import PackageLabel, ReportContext, render
from tests.helpers import make_finding

CONTEXT = ReportContext(packages=(PackageLabel("pkg", "src/pkg"), PackageLabel("b", "src/b")),
                        fixable={"MAN013": True})


def test_values() -> None:
    findings = [make_finding(), make_finding("MAN013", "warning", path="package.xml", line=0,
                                             col=0, fix=None)]
    document = json.loads(render("json", findings, context=CONTEXT))
    assert document["findings"] == [
        {"rule": "MAN013", "severity": "warning", "package": "pkg",
         "path": "src/pkg/package.xml", "line": None, "column": None,
         "message": "Python syntax error: invalid syntax", "fix": None, "fixable": "safe",
         "related": []},
        {"rule": "SYN001", "severity": "error", "package": "pkg", "path": "src/pkg/pkg/node.py",
         "line": 3, "column": 5, "message": "Python syntax error: invalid syntax",
         "fix": "Fix the syntax at the reported line and column", "fixable": None,
         "related": []},
    ]
    assert document["summary"] == {"error": 1, "warning": 1, "info": 0, "packages": 2}


def test_empty() -> None:
    document = json.loads(render("json", [], context=ReportContext()))
    assert document["findings"] == []
    assert document["summary"] == {"error": 0, "warning": 0, "info": 0, "packages": 0}
