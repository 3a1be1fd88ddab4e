"""Plain-text grading report: each submission's criteria with feedback, then a table.

Every label, package name, error and feedback line is one line of its own
(:func:`pkgtool.report.untrusted.line`): a student cannot add lines or terminal escapes.
"""

from __future__ import annotations

import io
from collections.abc import Sequence

from pkgtool.grade.report import points
from pkgtool.grade.results import SubmissionResult
from pkgtool.grade.rubric import Rubric
from pkgtool.report.untrusted import line


def render(results: Sequence[SubmissionResult], *, rubric: Rubric) -> str:
    """Details for every submission, and a summary table when there are several."""
    blocks = [_submission(r) for r in results]
    if len(results) > 1:
        blocks.append(summary_table(results, rubric=rubric))
    return "\n".join(blocks)


def _submission(result: SubmissionResult) -> str:
    package = f" ({line(result.package)})" if result.package else ""
    lines = [f"{line(result.label)}{package}: {points(result.score)} / "
             f"{points(result.max_score)}"]
    if result.error:
        lines.append(f"  not graded: {line(result.error)}")
    for criterion in result.criteria:
        mark = f"[{points(criterion.score)}/{points(criterion.max_score)}]"
        lines.append(f"  {mark:<9} {line(criterion.name)}")
        lines += [f"            {line(text)}" for text in criterion.feedback
                  if not text.startswith("Not graded:")]
    if not result.unchanged:
        lines.append("  WARNING: the submission changed on disk while it was graded")
    if result.isolation:
        lines.append(f"  sandbox: {line(result.isolation)}")
    lines.append(f"  graded in {result.seconds:.1f} s")
    return "\n".join(lines) + "\n"


def summary_table(results: Sequence[SubmissionResult], *, rubric: Rubric) -> str:
    """A table of every submission's score (rich, rendered to plain text; no markup read)."""
    from rich.console import Console
    from rich.table import Table
    from rich.text import Text

    table = Table(title=Text(f"{line(rubric.title)}: {len(results)} submissions"))
    for header, justify in (("Submission", "left"), ("Score", "right"), ("Max", "right"),
                            ("Time (s)", "right"), ("Note", "left")):
        table.add_column(header, justify=justify)  # type: ignore[arg-type]
    for r in results:
        lost = [c.name for c in r.criteria if not c.passed]
        note = r.error or (f"lost: {', '.join(lost)}" if lost else "full marks")
        table.add_row(Text(line(r.label)), points(r.score), points(r.max_score),
                      f"{r.seconds:.1f}", Text(line(note)))
    buffer = io.StringIO()
    Console(file=buffer, width=120, color_system=None, force_terminal=False).print(table)
    return buffer.getvalue()
