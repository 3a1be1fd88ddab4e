"""JUnit XML: the one writer (:func:`write`) of lint, test and grade, and lint's report.

The writer counts tests, failures, errors and skips from the cases, for every suite and for the
whole document, and passes every name and text through :mod:`pkgtool.report.untrusted`, so a
package or a student can neither break the XML nor forge a count.

lint: a test suite per package, a test case per rule with findings. A package with no
findings gets one passing ``lint`` test case. A rule's findings are a ``<failure>`` when any is
an error or a warning (``type`` is the worst severity); info-only findings go to
``<system-out>`` of a passing case.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Sequence
from itertools import groupby
from xml.etree import ElementTree as ET

from pkgtool.findings import Finding, Severity
from pkgtool.records import record
from pkgtool.report import PackageLabel, ReportContext, display_path
from pkgtool.report.text import finding_lines
from pkgtool.report.untrusted import block, line

OUTCOMES = ("passed", "failure", "error", "skipped")
"""A case's outcome; all but ``passed`` are the name of the element that says so."""


@record
class Case:
    """A ``<testcase>``: ``text`` is the body of its outcome element, ``output`` its stdout."""

    classname: str
    name: str
    outcome: str = "passed"
    message: str = ""
    text: str = ""
    output: str = ""
    kind: str = ""
    seconds: float | None = None
    file: str = ""


@record
class Suite:
    """A ``<testsuite>`` of cases."""

    name: str
    cases: tuple[Case, ...]
    seconds: float | None = None
    file: str = ""


def _counts(cases: Sequence[Case]) -> dict[str, str]:
    found = Counter(case.outcome for case in cases)
    return {"tests": str(len(cases)), "failures": str(found["failure"]),
            "errors": str(found["error"]), "skipped": str(found["skipped"])}


def _attributes(**values: object) -> dict[str, str]:
    """Attributes made safe; empty ones and unknown times left out."""
    return {key: line(value) if isinstance(value, str) else f"{value:.3f}"
            for key, value in values.items() if value not in ("", None)}


def _case(suite: ET.Element, case: Case) -> None:
    if case.outcome not in OUTCOMES:
        raise ValueError(f"unknown test outcome {case.outcome!r}")
    element = ET.SubElement(suite, "testcase", _attributes(
        classname=case.classname, name=case.name, time=case.seconds, file=case.file))
    if case.outcome != "passed":
        ET.SubElement(element, case.outcome, _attributes(
            message=case.message, type=case.kind)).text = block(case.text) or None
    if case.output:
        ET.SubElement(element, "system-out").text = block(case.output)


def write(title: str, suites: Sequence[Suite]) -> str:
    """A ``<testsuites>`` document, counts and times summed from the cases."""
    every = [case for suite in suites for case in suite.cases]
    times = [s.seconds for s in suites if s.seconds is not None]
    top = ET.Element("testsuites", _attributes(name=title, **_counts(every),
                                               time=sum(times) if times else None))
    for suite in suites:
        element = ET.SubElement(top, "testsuite", _attributes(
            name=suite.name, **_counts(suite.cases), time=suite.seconds, file=suite.file))
        for case in suite.cases:
            _case(element, case)
    ET.indent(top)
    return ET.tostring(top, encoding="unicode", xml_declaration=True) + "\n"


def _body(findings: Sequence[Finding]) -> str:
    return "\n".join(finding_lines(f) for f in findings)


def _rule_case(package: PackageLabel, findings: list[Finding], context: ReportContext) -> Case:
    """The test case of one rule's findings in one package."""
    code = findings[0].code
    rule = context.rules.get(code)
    name = f"{code} {rule.name}" if rule else code
    worst = max(findings, key=lambda f: f.severity.rank).severity
    if worst is Severity.INFO:
        return Case(package.name, name, output=_body(findings), file=display_path(findings[0]))
    count = len(findings)
    return Case(package.name, name, "failure",
                f"{count} finding{'s' * (count != 1)}: {findings[0].message}", _body(findings),
                kind=worst.value, file=display_path(findings[0]))


def render(findings: Sequence[Finding], *, context: ReportContext) -> str:
    """lint's findings: a test suite per package checked."""
    suites = []
    for package in context.packages:
        mine = sorted((f for f in findings if f.root == package.root), key=lambda f: f.code)
        cases = [_rule_case(package, list(group), context)
                 for _, group in groupby(mine, key=lambda f: f.code)]
        suites.append(Suite(package.name, tuple(cases) or (Case(package.name, "lint"),),
                            file=package.root))
    return write("pkgtool lint", suites)
