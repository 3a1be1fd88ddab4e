"""``pkgtool reference``: list, generate and test the course documents' reference packages.

Thin adapters over :mod:`pkgtool.commands.reference`; rich is imported only to draw tables and
the progress display.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Optional

import typer

from pkgtool.cli import examples
from pkgtool.commands import ExitCode

if TYPE_CHECKING:
    from rich.console import Console

    from pkgtool.commands.reference import TestRunResult

reference_app = typer.Typer(
    help="The packages the course documents describe: list, generate, lint, build and test.",
    no_args_is_help=True, epilog=examples(
        "pkgtool reference list", "pkgtool reference generate --all --dest ws/src",
        "pkgtool reference test robot_monitor"))

_NAMES = typer.Argument(metavar="NAME...", show_default=False,
                        help="Reference package names (see `pkgtool reference list`).")
_ALL = typer.Option("--all", help="Every reference package.")


def _fail(errors: tuple[str, ...], code: ExitCode) -> typer.Exit:
    for message in errors:
        typer.echo(f"pkgtool reference: {message}", err=True)
    return typer.Exit(int(code))


def _console() -> Console:
    from rich.console import Console

    return Console(highlight=False)


@reference_app.command("list", epilog=examples("pkgtool reference list"))
def list_command() -> None:
    """Show each reference package with its source document and nodes."""
    from rich.table import Table

    from pkgtool.commands.reference import list_packages

    result = list_packages()
    if result.errors:
        raise _fail(result.errors, result.exit_code)
    table = Table("package", "document", "nodes")
    for entry in result.entries:
        table.add_row(entry.name, entry.document, ", ".join(entry.nodes))
    _console().print(table)


@reference_app.command("generate", epilog=examples(
    "pkgtool reference generate robot_monitor --dest ws/src",
    "pkgtool reference generate --all --dest ws/src"))
def generate_command(
    names: Annotated[Optional[list[str]], _NAMES] = None,
    all_: Annotated[bool, _ALL] = False,
    dest: Annotated[Path, typer.Option(help="Folder to write the packages into.",
                                       metavar="DIR")] = Path("."),
) -> None:
    """Copy reference packages (and the support packages they need) into a folder."""
    from pkgtool.commands.reference import generate

    result = generate(names or (), all_=all_, dest=dest)
    for path in result.written:
        typer.echo(f"generated {path}")
    for path in result.kept:
        typer.echo(f"kept existing {path}")
    if result.errors:
        raise _fail(result.errors, result.exit_code)


@reference_app.command("test", epilog=examples(
    "pkgtool reference test robot_monitor nav_agent",
    "pkgtool reference test --all -j 2 --keep /tmp/reference-ws"))
def test_command(
    names: Annotated[Optional[list[str]], _NAMES] = None,
    all_: Annotated[bool, _ALL] = False,
    jobs: Annotated[Optional[int], typer.Option(
        "--jobs", "-j", min=1, help="Packages colcon builds and tests in parallel "
        "(default: colcon's, one per CPU).", show_default=False, metavar="N")] = None,
    keep: Annotated[Optional[Path], typer.Option(
        help="Build in this new or empty folder and keep it (default: a temporary folder).",
        show_default=False, metavar="DIR")] = None,
) -> None:
    """Generate into a workspace, lint --strict, colcon build and test; exit 1 on failures."""
    from pkgtool.commands.reference import run_tests

    console = _console()
    with _Progress(console) as report:
        result = run_tests(names or (), all_=all_, jobs=jobs, keep=keep, progress=report)
    if result.errors:
        raise _fail(result.errors, result.exit_code)
    _print_results(console, result)
    raise typer.Exit(int(result.exit_code))


class _Progress:
    """A live per-package progress display on a terminal; one line per event elsewhere (CI)."""

    def __init__(self, console: Console) -> None:
        self.console = console
        self.bar = None
        self.tasks: dict[str, int] = {}

    def __enter__(self):  # type: ignore[no-untyped-def]
        if self.console.is_terminal:
            from rich.progress import Progress, SpinnerColumn, TextColumn, TimeElapsedColumn

            self.bar = Progress(SpinnerColumn(), TextColumn("{task.description}"),
                                TimeElapsedColumn(), console=self.console, transient=True)
            self.bar.start()
        return self.report

    def report(self, name: str, stage: str) -> None:
        if self.bar is None:
            self.console.print(f"{name}: {stage}", markup=False)
            return
        if name not in self.tasks:
            self.tasks[name] = self.bar.add_task(name, total=None)
        self.bar.update(self.tasks[name], description=f"{name}: {stage}")

    def __exit__(self, *exc: object) -> None:
        if self.bar is not None:
            self.bar.stop()


def _print_results(console: Console, result: TestRunResult) -> None:
    from rich.table import Table

    table = Table(title="reference test")
    table.add_column("package", no_wrap=True)
    for column in ("lint findings", "build", "tests passed", "tests failed", "time"):
        table.add_column(column, justify="left" if column == "build" else "right")
    for report in result.packages:
        summary = report.summary
        if summary is None:
            passed, failed = "[dim]-[/]", "[dim]-[/]"
        else:
            bad = summary.counts["failed"] + summary.counts["error"]
            passed = f"[{'green' if summary.ok else 'red'}]{summary.passed}[/]"
            failed = f"[{'red' if bad else 'green'}]{bad}[/]"
        table.add_row(
            report.name,
            f"[{'red' if report.findings else 'green'}]{len(report.findings)}[/]",
            "[green]ok[/]" if report.built else "[red]failed[/]",
            passed, failed, f"{report.seconds:.1f} s")
    console.print(table)
    for report in result.packages:
        details = list(report.findings)
        if report.summary is not None:
            details += [f"{c.name}: {c.outcome}: {c.message}" for c in report.summary.cases
                        if c.outcome in ("failed", "error")]
            if report.summary.problem or not report.summary.ran:
                details.append(f"tests: {report.summary.describe()}")
        if not report.built and report.output:
            details.append(report.output)
        if details:
            console.print(f"[bold]{report.name}[/]", markup=True)
            console.print("\n".join(f"  {line}" for line in details), markup=False)
    if result.workspace is not None:
        console.print(f"workspace kept in {result.workspace}", markup=False)


def register(app: typer.Typer) -> None:
    """Attach ``reference`` and its subcommands to the root app."""
    app.add_typer(reference_app, name="reference")
