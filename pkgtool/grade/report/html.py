"""The class report: one self-contained HTML page for the instructor of a graded batch.

A histogram of scores (inline SVG), each criterion's pass rate, the lint rules most often
broken across the class, and a row per student linking to that student's feedback further
down the page. No script and no external resource: it opens offline from a file, and a
Content-Security-Policy forbids anything else. Student text goes through
:func:`pkgtool.report.html.text`.
"""

from __future__ import annotations

import statistics
from collections import Counter
from collections.abc import Sequence

from pkgtool.grade.report import points
from pkgtool.grade.results import SubmissionResult
from pkgtool.grade.rubric import Rubric
from pkgtool.report.html import page, text
from pkgtool.lazy_regex import lazy_pattern

BINS = 10
"""Histogram bars: scores as a share of the maximum, in tenths (the last bar holds 100 %)."""
_FINDING = lazy_pattern(r":\d+: ([A-Z]{3}\d{3}) ")
_STYLE = """body{font-family:system-ui,sans-serif;margin:2em;max-width:70em;color:#222}
table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #ccc;padding:.3em .6em}
th{background:#f3f3f3;text-align:left}td.num{text-align:right}.error{color:#a00}
pre{background:#f7f7f7;padding:.5em;overflow-x:auto;white-space:pre-wrap}
svg .bar{fill:#4a7bd0}svg text{font-size:11px;fill:#333}section{margin-top:2em}
"""


def histogram(results: Sequence[SubmissionResult], max_score: float) -> list[int]:
    """How many submissions fall in each of the :data:`BINS` bars."""
    counts = [0] * BINS
    for result in results:
        share = result.score / max_score if max_score > 0 else 0.0
        counts[min(BINS - 1, max(0, int(share * BINS)))] += 1
    return counts


def _svg(counts: list[int]) -> str:
    width, height, bar = 40 * BINS + 40, 220, 36
    top = max(counts) or 1
    parts = [f'<svg id="histogram" xmlns="http://www.w3.org/2000/svg" width="{width}" '
             f'height="{height}" role="img" aria-label="Score distribution">']
    for index, count in enumerate(counts):
        tall = round(160 * count / top)
        x, y = 30 + 40 * index, 180 - tall
        parts.append(f'<rect class="bar" data-bin="{index}" data-count="{count}" x="{x}" '
                     f'y="{y}" width="{bar}" height="{tall}"><title>{count}</title></rect>')
        parts.append(f'<text x="{x + bar / 2}" y="{y - 4}" text-anchor="middle">{count}</text>')
        top_of_bin = 100 if index == BINS - 1 else index * 10 + 9
        parts.append(f'<text x="{x + bar / 2}" y="198" text-anchor="middle">'
                     f'{index * 10}-{top_of_bin}</text>')
    parts.append('<text x="30" y="215">score, in % of the maximum</text></svg>')
    return "\n".join(parts)


def _criteria(results: Sequence[SubmissionResult], rubric: Rubric) -> str:
    graded = [r for r in results if r.error is None]
    rows = []
    for index, criterion in enumerate(rubric.criteria):
        outcomes = [r.criteria[index] for r in graded if index < len(r.criteria)]
        passed = sum(o.passed for o in outcomes)
        rate = f"{100 * passed / len(outcomes):.0f} %" if outcomes else "-"
        mean = points(statistics.fmean(o.score for o in outcomes)) if outcomes else "-"
        rows.append(f"<tr><td>{text(criterion.name)}</td><td>{text(criterion.kind)}</td>"
                    f'<td class="num">{passed} / {len(outcomes)}</td><td class="num">{rate}</td>'
                    f'<td class="num">{mean} / {points(criterion.points)}</td></tr>')
    return ("<table id=\"criteria\"><tr><th>criterion</th><th>kind</th><th>passed</th>"
            "<th>pass rate</th><th>mean points</th></tr>\n" + "\n".join(rows) + "</table>")


def rules_broken(results: Sequence[SubmissionResult]) -> list[tuple[str, int, int]]:
    """(rule code, students, findings) from the lint criteria's feedback, most students first."""
    students: Counter[str] = Counter()
    findings: Counter[str] = Counter()
    for result in results:
        codes = [m.group(1) for c in result.criteria if c.kind == "lint"
                 for line in c.feedback for m in [_FINDING.search(line)] if m]
        findings.update(codes)
        students.update(set(codes))
    return sorted(((code, students[code], findings[code]) for code in students),
                  key=lambda row: (-row[1], -row[2], row[0]))


def _rules(results: Sequence[SubmissionResult]) -> str:
    rows = [f'<tr><td>{code}</td><td class="num">{who}</td><td class="num">{count}</td></tr>'
            for code, who, count in rules_broken(results)[:15]]
    if not rows:
        return "<p>No lint criterion reported a finding.</p>"
    return ("<table id=\"rules\"><tr><th>rule</th><th>students</th><th>findings</th></tr>\n"
            + "\n".join(rows) + "</table>")


def _students(results: Sequence[SubmissionResult]) -> str:
    rows = []
    for index, result in enumerate(results):
        status = (f'<span class="error">{text(result.error)}</span>' if result.error
                  else "graded")
        rows.append(f'<tr><td><a href="#s{index}">{text(result.label)}</a></td>'
                    f"<td>{text(result.package or '')}</td>"
                    f'<td class="num" data-score="{result.score}">{points(result.score)} / '
                    f"{points(result.max_score)}</td><td>{status}</td></tr>")
    return ("<table id=\"students\"><tr><th>submission</th><th>package</th><th>score</th>"
            "<th>status</th></tr>\n" + "\n".join(rows) + "</table>")


def _feedback(index: int, result: SubmissionResult) -> str:
    parts = [f'<section id="s{index}"><h3>{text(result.label)}: {points(result.score)} / '
             f"{points(result.max_score)}</h3>"]
    if result.error:
        parts.append(f'<p class="error">{text(result.error)}</p>')
    for criterion in result.criteria:
        parts.append(f"<h4>{text(criterion.name)}: {points(criterion.score)} / "
                     f"{points(criterion.max_score)} ({text(criterion.visibility)})</h4>")
        if criterion.feedback:
            parts.append(f"<pre>{text(chr(10).join(criterion.feedback))}</pre>")
        if criterion.output:
            parts.append(f"<details><summary>output</summary><pre>{text(criterion.output)}"
                         "</pre></details>")
    parts.append('<p><a href="#students">back to the class</a></p></section>')
    return "\n".join(parts)


def render(results: Sequence[SubmissionResult], *, rubric: Rubric) -> str:
    """The class report of ``results`` graded with ``rubric``."""
    scores = [r.score for r in results]
    summary = (f"{len(results)} submissions, mean {points(statistics.fmean(scores))}, median "
               f"{points(statistics.median(scores))} of {points(rubric.max_score)}"
               if scores else "no submissions")
    body = [f"<h1>{text(rubric.title)}</h1>", f"<p id=\"summary\">{summary}</p>",
            "<h2>Score distribution</h2>", _svg(histogram(results, rubric.max_score)),
            "<h2>Criteria</h2>", _criteria(results, rubric),
            "<h2>Lint rules most often broken</h2>", _rules(results),
            "<h2>Students</h2>", _students(results),
            "<h2>Feedback</h2>", *(_feedback(i, r) for i, r in enumerate(results))]
    return page(f"{rubric.title}: class report", _STYLE, "\n".join(body) + "\n")
