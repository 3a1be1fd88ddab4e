"""JUnit XML for CI test views: a test suite per package, a test case per rule with findings.

A package with no findings gets one passing ``lint`` test case. A rule's findings are a
``<failure>`` when any is an error or a warning (``type`` is the worst severity); info-only
findings go to ``<system-out>`` of a passing case. Built with the standard library.
"""

from __future__ import annotations

from collections.abc import Sequence
from itertools import groupby
from xml.etree import ElementTree as ET

from pkgtool.findings import Finding, Severity
from pkgtool.report import PackageLabel, ReportContext, display_path
from pkgtool.report.text import location


def _body(findings: Sequence[Finding]) -> str:
    return "\n".join(f"{location(f)}: {f.code} {f.message}" + (f"\n  help: {f.fix}" * bool(f.fix))
                     for f in findings)


def _case(suite: ET.Element, package: PackageLabel, findings: list[Finding],
          context: ReportContext) -> bool:
    """Add the test case of one rule's findings; True when it failed."""
    code = findings[0].code
    rule = context.rules.get(code)
    case = ET.SubElement(suite, "testcase", classname=package.name,
                         name=f"{code} {rule.name}" if rule else code,
                         file=display_path(findings[0]))
    worst = max(findings, key=lambda f: f.severity.rank).severity
    if worst is Severity.INFO:
        ET.SubElement(case, "system-out").text = _body(findings)
        return False
    count = len(findings)
    failure = ET.SubElement(case, "failure", type=worst.value,
                            message=f"{count} finding{'s' * (count != 1)}: {findings[0].message}")
    failure.text = _body(findings)
    return True


def render(findings: Sequence[Finding], *, context: ReportContext) -> str:
    """A ``<testsuites>`` document covering every package checked."""
    top = ET.Element("testsuites", name="pkgtool lint")
    total_tests = total_failures = 0
    for package in context.packages:
        suite = ET.SubElement(top, "testsuite", name=package.name, file=package.root)
        mine = sorted((f for f in findings if f.root == package.root), key=lambda f: f.code)
        groups = [list(group) for _, group in groupby(mine, key=lambda f: f.code)]
        failures = sum(_case(suite, package, group, context) for group in groups)
        if not groups:
            ET.SubElement(suite, "testcase", classname=package.name, name="lint")
        tests = max(len(groups), 1)
        suite.set("tests", str(tests))
        suite.set("failures", str(failures))
        total_tests += tests
        total_failures += failures
    top.set("tests", str(total_tests))
    top.set("failures", str(total_failures))
    ET.indent(top)
    return ET.tostring(top, encoding="unicode", xml_declaration=True) + "\n"
