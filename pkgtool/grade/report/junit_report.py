"""JUnit XML grading report: a test suite per submission, a test case per criterion."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Sequence

from pkgtool.grade.report import points
from pkgtool.grade.results import SubmissionResult
from pkgtool.grade.rubric import Rubric


def render(results: Sequence[SubmissionResult], *, rubric: Rubric) -> str:
    """The results as JUnit XML; a criterion below full marks is a failure."""
    root = ET.Element("testsuites", name=f"pkgtool grade: {rubric.title}")
    for result in results:
        failures = sum(1 for c in result.criteria if not c.passed)
        suite = ET.SubElement(root, "testsuite", name=result.label,
                              tests=str(len(result.criteria)), failures=str(failures),
                              errors="1" if result.error else "0", time=f"{result.seconds:.2f}")
        for criterion in result.criteria:
            case = ET.SubElement(suite, "testcase", classname=result.label, name=criterion.name,
                                 time="0")
            text = "\n".join(criterion.feedback)
            if not criterion.passed:
                failure = ET.SubElement(case, "failure", message=f"{points(criterion.score)} of "
                                        f"{points(criterion.max_score)} points")
                failure.text = text
            if criterion.output:
                ET.SubElement(case, "system-out").text = criterion.output
    ET.indent(root)
    return ET.tostring(root, encoding="unicode", xml_declaration=True) + "\n"
