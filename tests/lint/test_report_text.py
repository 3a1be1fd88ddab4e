"""Text report: ``path:line:col: CODE message``, ``  help: fix``, a summary, optional colour."""

from __future__ import annotations

from pkgtool.report import PackageLabel, ReportContext, render
from tests.helpers import make_finding

TWO = ReportContext(packages=(PackageLabel("pkg", "src/pkg"), PackageLabel("other", "src/other")))


def test_lines_are_sorted_by_path_line_column_and_code() -> None:
    findings = [make_finding("SYN002", line=9),
                make_finding("MAN001", "warning", path="package.xml", line=2, col=0),
                make_finding("SYN001", line=3), make_finding("DEP001", "info", line=3)]
    assert render("text", findings, context=TWO) == (
        "src/pkg/package.xml:2: MAN001 Python syntax error: invalid syntax\n"
        "  help: Fix the syntax at the reported line and column\n"
        "src/pkg/pkg/node.py:3:5: DEP001 Python syntax error: invalid syntax\n"
        "  help: Fix the syntax at the reported line and column\n"
        "src/pkg/pkg/node.py:3:5: SYN001 Python syntax error: invalid syntax\n"
        "  help: Fix the syntax at the reported line and column\n"
        "src/pkg/pkg/node.py:9:5: SYN002 Python syntax error: invalid syntax\n"
        "  help: Fix the syntax at the reported line and column\n"
        "Found 2 errors, 1 warning, 1 info in 1 of 2 packages.\n")


def test_unknown_position_and_package_level_findings() -> None:
    whole = make_finding(path="", line=0, col=0, fix=None)
    assert render("text", [whole], context=TWO).splitlines()[0] == (
        "src/pkg: SYN001 Python syntax error: invalid syntax")
    here = make_finding(root=".", path="setup.py", line=4, col=0)
    assert render("text", [here], context=TWO).startswith("setup.py:4: SYN001 ")


def test_no_findings_summary() -> None:
    assert render("text", [], context=ReportContext((PackageLabel("a", "a"),))) == (
        "No findings in 1 package.\n")


def test_colour_only_when_asked() -> None:
    plain = render("text", [make_finding()], context=TWO)
    assert "\x1b[" not in plain
    coloured = render("text", [make_finding()], context=ReportContext(TWO.packages, color=True))
    assert "\x1b[" in coloured
    assert "src/pkg/pkg/node.py:3:5:" in coloured and "SYN001" in coloured
