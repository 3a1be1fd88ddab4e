"""The ``pkgtool`` command line: thin typer adapters over ``pkgtool.commands``.

Each verb lives in ``pkgtool/cli_<verb>.py`` as a function registered here; command bodies parse
options, call ``pkgtool.commands.<verb>.run(...)``, render the result and exit with its code.
"""

from __future__ import annotations

from typing import Annotated, Optional

import typer

from pkgtool import __version__

app = typer.Typer(
    name="pkgtool",
    help="Create, lint, check, test and grade ROS 2 Python (ament_python) packages.",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
    rich_markup_mode=None,  # plain help: loading rich would triple `pkgtool --help` time
)


def _version(value: bool) -> None:
    if value:
        typer.echo(f"pkgtool {__version__}")
        raise typer.Exit(0)


@app.callback()
def _root(
    version: Annotated[
        Optional[bool],
        typer.Option("--version", callback=_version, is_eager=True,
                     help="Print the version and exit."),
    ] = None,
) -> None:
    """Create, lint, check, test and grade ROS 2 Python (ament_python) packages."""


def _register() -> None:
    """Attach each verb's command module (imported lazily inside the commands themselves)."""
    import importlib

    for verb in VERBS:
        importlib.import_module(f"pkgtool.cli_{verb}").register(app)


VERBS: tuple[str, ...] = ("lint", "create", "add", "test", "grade", "reference")
"""Verbs with a ``pkgtool/cli_<verb>.py`` exposing ``register(app)``; add a verb when it works."""


def main() -> None:
    """Console-script entry point."""
    _register()
    app()
