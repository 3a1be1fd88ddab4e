"""``pkgtool test``: parse options, call :mod:`pkgtool.commands.test`, render, exit."""

from __future__ import annotations

from enum import Enum
from pathlib import Path
from typing import Annotated, Optional

import typer

from pkgtool.cli import examples
from pkgtool.cli_grade import SANDBOX_HELP, SandboxMode
from pkgtool.cli_output import check_output, emit


class Format(str, Enum):
    """Report formats of ``pkgtool test``."""

    TEXT = "text"
    JSON = "json"
    JUNIT = "junit"


def test(
    path: Annotated[str, typer.Argument(
        help="A package folder, or a workspace to test all of.", metavar="PATH")],
    timeout: Annotated[float, typer.Option(
        help="Wall-clock seconds for the build, and again for the tests.", min=1,
        metavar="SECONDS")] = 600.0,
    test_timeout: Annotated[Optional[float], typer.Option(
        help="Seconds per single test (needs pytest-timeout).", min=1,
        show_default=False, metavar="SECONDS")] = None,
    fmt: Annotated[Format, typer.Option("--format", "-f", help="Report format.")] = Format.TEXT,
    output: Annotated[Optional[Path], typer.Option(
        "--output", "-o", help="Write the report to this file instead of stdout.",
        dir_okay=False, metavar="FILE")] = None,
    sandbox: Annotated[SandboxMode, typer.Option(help=SANDBOX_HELP)] = SandboxMode.AUTO,
) -> None:
    """Build a package with colcon in a temporary sandboxed workspace and run its tests.

    Sibling packages it depends on (from the workspace's src folder) are built too; the
    source tree is never written to. Exit codes: 0 tests ran and all passed, 1 a build
    failure, a failing test or no tests at all, 2 usage error.
    """
    from pkgtool.commands.test import run
    from pkgtool.grade.report.package_tests import render
    from pkgtool.report.untrusted import block

    check_output(output, "test")
    result = run(path, timeout=timeout, test_timeout=test_timeout,
                 mode=None if sandbox is SandboxMode.AUTO else sandbox.value)
    for message in result.errors:
        typer.echo(f"pkgtool test: {block(message)}", err=True)
    if result.packages:
        emit(render(fmt.value, result.packages, isolation=result.isolation), output, "test")
    raise typer.Exit(int(result.exit_code))


def register(app: typer.Typer) -> None:
    """Attach ``test`` to the root app."""
    app.command("test", epilog=examples(
        "pkgtool test src/my_robot", "pkgtool test ws/ --format junit -o results.xml",
        "pkgtool test src/my_robot --test-timeout 60"))(test)
