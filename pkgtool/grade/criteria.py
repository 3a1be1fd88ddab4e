"""Score each kind of rubric criterion for one prepared job, with feedback for the student."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from pkgtool.engine import Selection, check_package
from pkgtool.findings import Severity
from pkgtool.testresults import TestSummary
from pkgtool.grade.results import CriterionResult
from pkgtool.grade.rubric import Criterion, Rubric
from pkgtool.grade.runner import WorkspaceRunner, first_error
from pkgtool.model.package import Package
from pkgtool.ros.colcon import ColconRun

MAX_LINES = 20


@dataclass
class Job:
    """One submission ready to grade: its workspace runner, target package and cached runs."""

    rubric: Rubric
    runner: WorkspaceRunner
    package: Package
    _build: ColconRun | None = None
    _runs: dict[str, tuple[ColconRun, TestSummary]] = field(default_factory=dict)

    @property
    def name(self) -> str:
        """The graded package's name."""
        return self.package.name

    def build(self) -> ColconRun:
        """The (single) colcon build of the job."""
        if self._build is None:
            self._build = self.runner.build([self.name])
        return self._build

    def tests(self, exclude: tuple[str, ...]) -> tuple[ColconRun, TestSummary]:
        """The student's own tests, run once per distinct ``exclude`` list."""
        key = "tests:" + ",".join(exclude)
        if key not in self._runs:
            self._runs[key] = self.runner.test(self.name, test_timeout=self.rubric.test_timeout,
                                               ignore=exclude)
        return self._runs[key]

    def hidden(self, folder: Path) -> tuple[ColconRun, TestSummary]:
        """Instructor tests from ``folder``, run against the installed workspace."""
        key = f"hidden:{folder}"
        if key not in self._runs:
            self._runs[key] = self.runner.pytest(folder, test_timeout=self.rubric.test_timeout)
        return self._runs[key]


STATIC = ("lint", "style")
"""Kinds that only read the submission: graded before any of its code runs."""


def evaluate_all(job: Job) -> tuple[CriterionResult, ...]:
    """Every criterion of the rubric, static ones first, reported in the rubric's order."""
    criteria = job.rubric.criteria
    order = sorted(range(len(criteria)), key=lambda i: criteria[i].kind not in STATIC)
    results = {i: evaluate(criteria[i], job) for i in order}
    return tuple(results[i] for i in range(len(criteria)))


def evaluate(criterion: Criterion, job: Job) -> CriterionResult:
    """Score ``criterion`` on ``job``; the rubric's feedback is added when marks are lost."""
    if criterion.kind in STATIC:
        score, lines, output = _lint(criterion, job)
    elif criterion.kind == "build":
        score, lines, output = _build(criterion, job)
    elif not job.build().ok:
        score, lines, output = 0.0, ["Not checked: the package does not build"], ""
    else:
        score, lines, output = _AFTER_BUILD[criterion.kind](criterion, job)
    score = round(max(0.0, min(criterion.points, score)), 2)
    if score < criterion.points and criterion.feedback:
        lines = [*lines, criterion.feedback]
    return CriterionResult(criterion.name, criterion.kind, score, criterion.points,
                           tuple(lines), output, criterion.visibility)


Outcome = tuple[float, list[str], str]


def _build(criterion: Criterion, job: Job) -> Outcome:
    run = job.build()
    if run.ok:
        return criterion.points, [f"`colcon build` succeeded in {run.seconds:.1f} s"], ""
    why = f" ({run.limit})" if run.limit else ""
    first = first_error(run.output)
    return 0.0, [f"`colcon build` failed{why}", *([first] if first else [])], _tail(run.output)


def _lint(criterion: Criterion, job: Job) -> Outcome:
    rules = Selection(select=criterion.select, ignore=criterion.ignore).rules()
    floor = Severity(criterion.min_severity).rank
    findings = check_package(job.package, rules, root_label=job.name)
    broken = [f"Not counted (a pkgtool bug): {f.message}" for f in findings if f.internal]
    found = [f for f in findings if f.severity.rank >= floor and not f.internal]
    if not found:
        return criterion.points, [f"No findings from {', '.join(criterion.select)}",
                                  *broken], ""
    lines = [f"{f.span.path}:{f.span.line}: {f.code} {f.message}" for f in found[:MAX_LINES]]
    lines += broken
    if len(found) > MAX_LINES:
        lines.append(f"... and {len(found) - MAX_LINES} more")
    if criterion.per_finding is None:
        return 0.0, lines, ""
    return criterion.points - criterion.per_finding * len(found), lines, ""


def _executables(criterion: Criterion, job: Job) -> Outcome:
    problems = job.runner.entry_points(job.name, criterion.names,
                                       timeout=job.rubric.test_timeout)
    good = [name for name, problem in problems.items() if not problem]
    lines = [problem or f"`{name}` is installed and loads" for name, problem in problems.items()]
    return _credit(criterion, len(good), len(problems)), lines, ""


def _tests(criterion: Criterion, job: Job) -> Outcome:
    run, summary = job.tests(criterion.exclude)
    if summary.problem:
        return 0.0, [summary.problem, *_limit(run)], _tail(run.output)
    if summary.ran < criterion.min_tests:
        found = f"only {summary.ran} tests ran" if summary.ran else "no tests ran"
        return 0.0, [f"{found}; write at least {criterion.min_tests} test(s)",
                     *_limit(run)], _tail(run.output)
    return _test_outcome(criterion, run, summary)


def _hidden(criterion: Criterion, job: Job) -> Outcome:
    assert criterion.path is not None
    run, summary = job.hidden(criterion.path)
    if not summary.ran:
        output = "" if criterion.details == "summary" else _tail(run.output)
        return 0.0, [summary.problem or "no instructor test ran", *_limit(run)], output
    return _test_outcome(criterion, run, summary)


def _test_outcome(criterion: Criterion, run: ColconRun, summary: TestSummary) -> Outcome:
    lines = [summary.describe(), *_limit(run)]
    failing = [c for c in summary.cases if c.outcome in ("failed", "error")]
    lines += [f"{c.outcome.upper()} {c.name}: {_first_line(c.message)}"
              for c in failing[:MAX_LINES]]
    if criterion.details == "summary":
        output = "\n".join(f"{c.outcome.upper():7} {c.name}"
                           + (f"\n        {_first_line(c.message)}" if c in failing else "")
                           for c in summary.cases)
    else:
        output = "\n".join(f"{c.outcome.upper():7} {c.name} ({c.seconds:.2f} s)"
                           + (f"\n{c.details}" if c.details else "") for c in summary.cases)
    return _credit(criterion, summary.passed, summary.ran), lines, output


def _first_line(message: str) -> str:
    """The exception and its message, without pytest's assertion explanation or source."""
    return (message.splitlines() or [""])[0]


def _credit(criterion: Criterion, good: int, total: int) -> float:
    if not total:
        return 0.0
    if criterion.partial:
        return criterion.points * good / total
    return criterion.points if good == total else 0.0


def _limit(run: ColconRun) -> list[str]:
    return [f"Stopped: {run.limit}"] if run.limit else []


def _tail(text: str, lines: int = 60) -> str:
    return "\n".join(text.splitlines()[-lines:])


_AFTER_BUILD: dict[str, Callable[[Criterion, Job], Outcome]] = {
    "executables": _executables, "tests": _tests, "hidden": _hidden}
