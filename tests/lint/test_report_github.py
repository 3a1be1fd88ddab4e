"""GitHub Actions annotations: one workflow command per finding, properly escaped."""

from __future__ import annotations

from pkgtool.report import ReportContext, render
from tests.helpers import make_finding


def test_levels_and_properties() -> None:
    findings = [make_finding(), make_finding("MAN013", "warning", path="package.xml", line=7,
                                             col=0, fix=None),
                make_finding("DEP010", "info", path="", line=0, col=0, fix=None)]
    assert render("github", findings, context=ReportContext()).splitlines() == [
        "::notice file=src/pkg,title=DEP010::Python syntax error: invalid syntax",
        "::warning file=src/pkg/package.xml,line=7,title=MAN013::"
        "Python syntax error: invalid syntax",
        "::error file=src/pkg/pkg/node.py,line=3,col=5,title=SYN001::"
        "Python syntax error: invalid syntax"
        "%0Ahelp: Fix the syntax at the reported line and column",
    ]


def test_escaping() -> None:
    finding = make_finding(root="a,b:c", message="100% sure\r\nreally\rnot\x1b[2J", fix=None)
    line = render("github", [finding], context=ReportContext())
    assert line == ("::error file=a%2Cb%3Ac/pkg/node.py,line=3,col=5,title=SYN001::"
                    "100%25 sure%0Areally\\x0dnot\\x1b[2J\n")


def test_nothing_to_annotate() -> None:
    assert render("github", [], context=ReportContext()) == ""
