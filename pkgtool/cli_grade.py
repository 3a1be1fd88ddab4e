"""``pkgtool grade``: parse options, call :mod:`pkgtool.commands.grade`, render, exit."""

from __future__ import annotations

import os
import sys
from enum import Enum
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Optional

import typer

from pkgtool.cli import examples
from pkgtool.cli_output import check_output, emit
from pkgtool.commands import ExitCode

if TYPE_CHECKING:
    from pkgtool.commands.grade import GradeResult
    from pkgtool.grade.results import SubmissionResult
    from pkgtool.grade.rubric import Rubric


class Format(str, Enum):
    """Report formats of ``pkgtool grade`` (see ``pkgtool.grade.report``)."""

    TEXT = "text"
    JSON = "json"
    JUNIT = "junit"
    GRADESCOPE = "gradescope"
    CSV = "csv"
    HTML = "html"


class SandboxMode(str, Enum):
    """Sandbox modes (see docs/grading.md): the strongest available, or one forced."""

    AUTO = "auto"
    ROOT = "root"
    USERNS = "userns"
    NONE = "none"


SANDBOX_HELP = ("Isolation of the builds and tests: auto (the strongest this machine allows), "
                "root (namespaces, own uid, cgroups), userns (namespaces without root), or "
                "none (limits and a process group only).")


def _fail(*messages: str) -> typer.Exit:
    from pkgtool.report.untrusted import block

    for message in messages:
        typer.echo(f"pkgtool grade: {block(message)}", err=True)
    return typer.Exit(int(ExitCode.USAGE))


def grade(
    submissions: Annotated[Optional[list[str]], typer.Argument(
        help="Packages, workspaces or .zip/.tar.gz archives (with --batch: folders of them).",
        show_default=False, metavar="SUBMISSION...")] = None,
    rubric: Annotated[Optional[str], typer.Option(
        "--rubric", "-r", help="The rubric TOML file.  [required, except with --init-rubric]",
        show_default=False, metavar="FILE")] = None,
    batch: Annotated[bool, typer.Option(
        help="Each SUBMISSION is a folder whose entries are submissions.")] = False,
    jobs: Annotated[int, typer.Option("--jobs", "-j", help="Submissions graded at once.",
                                      min=1, metavar="N")] = 1,
    fmt: Annotated[Format, typer.Option("--format", "-f", help="Report format.")] = Format.TEXT,
    output: Annotated[Optional[Path], typer.Option(
        "--output", "-o", help="Write the report to this file instead of stdout.",
        dir_okay=False, metavar="FILE")] = None,
    init_rubric: Annotated[Optional[Path], typer.Option(
        help="Write a commented example rubric (and hidden_tests/) to this file and exit.",
        dir_okay=False, show_default=False, metavar="FILE")] = None,
    export_gradescope: Annotated[Optional[Path], typer.Option(
        help="Write a Gradescope autograder bundle (setup.sh, run_autograder, the rubric and "
        "its hidden tests, pkgtool's wheel, the locked ROS 2 wheels' list) for --rubric to "
        "this .zip and exit.", dir_okay=False, show_default=False, metavar="FILE")] = None,
    cache: Annotated[Optional[str], typer.Option(
        help="Reuse results stored in this folder; grade only submissions and criteria that "
        "changed.", show_default=False, metavar="DIR")] = None,
    sandbox: Annotated[SandboxMode, typer.Option(help=SANDBOX_HELP)] = SandboxMode.AUTO,
) -> None:
    """Grade student submissions against a rubric, each built and tested in a sandbox.

    With --output the report file is rewritten as each submission finishes. Exit codes:
    0 graded (whatever the scores), 2 usage error (bad rubric, missing path).
    """
    from pkgtool.commands import grade as command

    if init_rubric is not None:
        done = command.init_rubric(init_rubric)
        if done.errors:
            raise _fail(*done.errors)
        for path in done.written:
            typer.echo(f"wrote {path}", err=True)
        raise typer.Exit(0)
    if rubric is None:
        raise _fail("Give the rubric with --rubric FILE (create one with --init-rubric FILE).")
    if export_gradescope is not None:
        done = command.export_gradescope(Path(rubric), export_gradescope)
        if done.errors:
            raise _fail(*done.errors)
        typer.echo(f"wrote {export_gradescope}: {', '.join(done.written)}", err=True)
        raise typer.Exit(0)
    check_output(output, "grade")
    mode = None if sandbox is SandboxMode.AUTO else sandbox.value
    result = _run(command, submissions or [], rubric, batch, jobs, fmt, mode, output, cache)
    if result.errors:
        raise _fail(*result.errors)
    from pkgtool.grade.report import render

    assert result.rubric is not None
    emit(render(fmt.value, result.results, rubric=result.rubric), output, "grade")
    raise typer.Exit(int(result.exit_code))


def _run(command, submissions: list[str], rubric: str, batch: bool,  # type: ignore[no-untyped-def]
         jobs: int, fmt: Format, mode: str | None, output: Optional[Path],
         cache: str | None = None) -> GradeResult:
    """Grade, with a progress bar on an interactive stderr when there are several."""
    from rich.console import Console
    from rich.markup import escape
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn

    from pkgtool.report.untrusted import line

    if fmt is Format.GRADESCOPE and (batch or len(submissions) != 1):
        raise _fail("The gradescope format takes exactly one submission (not --batch).")
    progress = Progress(TextColumn("grading"), BarColumn(), MofNCompleteColumn(),
                        TextColumn("{task.description}"), transient=True,
                        console=Console(stderr=True), disable=not sys.stderr.isatty())
    task = progress.add_task("", total=None)
    partial = _PartialReport(fmt, output)

    def started(total: int, loaded: Rubric) -> None:
        progress.update(task, total=total)
        partial.rubric = loaded

    def finished(result: SubmissionResult) -> None:
        progress.update(task, advance=1, description=escape(line(result.label)))
        partial.add(result)

    with progress:
        return command.run(submissions, rubric=rubric, batch=batch, jobs=jobs, mode=mode,
                           cache=cache, on_start=started, on_done=finished)


class _PartialReport:
    """Rewrites the --output file (atomically) with every result so far, as jobs end."""

    def __init__(self, fmt: Format, output: Optional[Path]) -> None:
        self.fmt, self.output = fmt, output
        self.rubric: Rubric | None = None
        self.results: list[SubmissionResult] = []

    def add(self, result: SubmissionResult) -> None:
        self.results.append(result)
        if self.output is None or self.rubric is None:
            return
        from pkgtool.grade.report import render

        temporary = self.output.with_name(f".{self.output.name}.partial")
        try:
            temporary.write_text(render(self.fmt.value, self.results, rubric=self.rubric),
                                 encoding="utf-8")
            os.replace(temporary, self.output)
        except OSError:
            pass  # the final write reports the problem


def register(app: typer.Typer) -> None:
    """Attach ``grade`` to the root app."""
    app.command("grade", options_metavar="--rubric FILE [OPTIONS]", epilog=examples(
        "pkgtool grade --init-rubric rubric.toml     # a commented example to start from",
        "pkgtool grade --rubric rubric.toml submissions/alice.zip",
        "pkgtool grade -r rubric.toml --batch submissions/ -j 2 -f csv -o grades.csv",
        "pkgtool grade -r rubric.toml --batch submissions/ -f html -o report.html",
        "pkgtool grade -r rubric.toml --export-gradescope autograder.zip"))(grade)
