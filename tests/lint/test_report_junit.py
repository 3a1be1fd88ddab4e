"""JUnit XML: a suite per package, a case per rule with findings, passing packages included."""

from __future__ import annotations

from xml.etree import ElementTree as ET

from pkgtool.report import PackageLabel, ReportContext, render
from pkgtool.rules.registry import load_all
from tests.helpers import make_finding

CONTEXT = ReportContext(packages=(PackageLabel("pkg", "src/pkg"), PackageLabel("ok", "src/ok")),
                        rules=load_all())


def test_suites_cases_and_failures() -> None:
    findings = [make_finding(), make_finding(line=9), make_finding("SYN002", "info"),
                make_finding("SYN003", "warning", path="package.xml")]
    top = ET.fromstring(render("junit", findings, context=CONTEXT))
    assert (top.tag, top.get("tests"), top.get("failures")) == ("testsuites", "4", "2")
    pkg, ok = top.findall("testsuite")
    assert (pkg.get("name"), pkg.get("tests"), pkg.get("failures")) == ("pkg", "3", "2")
    cases = {case.get("name"): case for case in pkg.findall("testcase")}
    assert list(cases) == ["SYN001 unparsable-file", "SYN002 unreadable-file",
                           "SYN003 xml-entity-declaration"]
    failure = cases["SYN001 unparsable-file"].find("failure")
    assert failure is not None and failure.get("type") == "error"
    assert failure.get("message", "").startswith("2 findings: ")
    assert "src/pkg/pkg/node.py:9:5: SYN001" in (failure.text or "")
    assert cases["SYN002 unreadable-file"].find("failure") is None
    assert "SYN002" in (cases["SYN002 unreadable-file"].findtext("system-out") or "")
    assert cases["SYN003 xml-entity-declaration"].find("failure").get("type") == "warning"
    assert [(c.get("name"), list(c)) for c in ok.findall("testcase")] == [("lint", [])]


def test_declaration_and_escaping() -> None:
    text = render("junit", [make_finding(message="a <b> & \"c\"")], context=CONTEXT)
    assert text.startswith("<?xml version='1.0' encoding='utf-8'?>")
    assert ET.fromstring(text).find(".//failure").text.startswith(
        "src/pkg/pkg/node.py:3:5: SYN001 a <b> & \"c\"")
