"""Human output: ``path:line:col: CODE message``, an indented ``help:`` line, then a summary.

Paths and messages pass through :func:`pkgtool.report.untrusted.line`: a file name or a quoted
file content can neither start a line of its own nor send terminal escapes.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from pkgtool.findings import Finding
from pkgtool.report import ReportContext, counts, display_path, fix_safety
from pkgtool.report.untrusted import line

_STYLES = {"error": "bold red", "warning": "yellow", "info": "blue"}


def location(finding: Finding) -> str:
    """``path:line:col`` with unknown (0) line or column left out."""
    parts = [line(display_path(finding))]
    if finding.span.line:
        parts.append(str(finding.span.line))
        if finding.span.col:
            parts.append(str(finding.span.col))
    return ":".join(parts)


def finding_lines(finding: Finding) -> str:
    """``path:line:col: CODE message`` and, when there is a fix, an indented ``help:`` line."""
    first = f"{location(finding)}: {finding.code} {line(finding.message)}"
    return first + (f"\n  help: {line(finding.fix)}" if finding.fix else "")


def _mark(finding: Finding, fixable: Mapping[str, bool]) -> str:
    """`` [*]`` after a code ``--fix`` repairs, `` [-]`` for an ``--unsafe-fixes`` one;
    nothing for a finding its fixer will refuse (``manual``)."""
    safe = fix_safety(finding, fixable)
    return "" if safe is None else " [*]" if safe else " [-]"


def _fixable_note(findings: Sequence[Finding], fixable: Mapping[str, bool]) -> str:
    kinds = [fix_safety(f, fixable) for f in findings]
    safe, unsafe = kinds.count(True), kinds.count(False)
    parts = [f"[*] {safe} fixable with `--fix`"] if safe else []
    if unsafe:
        parts.append(f"[-] {unsafe} more with `--fix --unsafe-fixes`")
    return "; ".join(parts) + "." if parts else ""


def summary(findings: Sequence[Finding], packages: int) -> str:
    """One line: how many findings of each severity, in how many packages."""
    noun = "package" if packages == 1 else "packages"
    if not findings:
        return f"No findings in {packages} {noun}."
    number = counts(findings)
    parts = [_plural(number["error"], "error"), _plural(number["warning"], "warning"),
             f"{number['info']} info"]
    affected = len({f.root for f in findings})
    return f"Found {', '.join(parts)} in {affected} of {packages} {noun}."


def _plural(count: int, word: str) -> str:
    return f"{count} {word}" if count == 1 else f"{count} {word}s"


def _lines(findings: Sequence[Finding], packages: int, fixable: Mapping[str, bool]
           ) -> list[list[tuple[str, str]]]:
    """Each output line as (text, rich style) segments."""
    lines = []
    for finding in findings:
        lines.append([(f"{location(finding)}:", "bold"),
                      (f" {finding.code}", _STYLES[finding.severity.value]),
                      (_mark(finding, fixable), "bold"),
                      (f" {line(finding.message)}", "")])
        if finding.fix:
            lines.append([(f"  help: {line(finding.fix)}", "dim")])
    lines.append([(summary(findings, packages), "bold")])
    note = _fixable_note(findings, fixable)
    if note:
        lines.append([(note, "")])
    return lines


def render(findings: Sequence[Finding], *, context: ReportContext) -> str:
    """The findings, each with its help line, and a summary; ANSI colour when asked."""
    lines = _lines(findings, len(context.packages), context.fixable)
    if not context.color:
        return "".join("".join(text for text, _ in segments) + "\n" for segments in lines)
    import io

    from rich.console import Console
    from rich.text import Text

    buffer = io.StringIO()
    console = Console(file=buffer, force_terminal=True, color_system="standard", width=100_000,
                      highlight=False, soft_wrap=True)
    for segments in lines:
        console.print(Text.assemble(*segments))
    return buffer.getvalue()
