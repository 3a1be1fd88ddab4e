"""The ``pkgtool`` command line: thin typer adapters over ``pkgtool.commands``.

Each verb lives in ``pkgtool/cli_<verb>.py`` as a function registered here; command bodies parse
options, call ``pkgtool.commands.<verb>.run(...)``, render the result and exit with its code.
Conventions of every command: ``-h``/``--help``, examples at the end of each help text, and
Ctrl-C ends the run with one line, "Interrupted: nothing was written", and exit code 130.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Sequence
from typing import Annotated, Optional

import typer

from pkgtool import __version__
from pkgtool.cli_fast import COMPLETION_VARIABLE, INTERRUPTED, finish
from pkgtool.cli_output import closed_pipe
HELP = {"help_option_names": ["-h", "--help"]}

app = typer.Typer(
    name="pkgtool",
    help="Create, lint, check, test and grade ROS 2 Python (ament_python) packages.",
    no_args_is_help=True,
    add_completion=True,  # --install-completion / --show-completion; costs no start-up time
    pretty_exceptions_enable=False,
    rich_markup_mode=None,  # plain help: loading rich would triple `pkgtool --help` time
    context_settings=HELP,
)


def examples(*lines: str) -> str:
    """An ``Examples:`` epilog kept as written (``\\b`` stops click from re-wrapping it)."""
    return "Examples:\n\n\b\n" + "\n".join(f"  {line}" for line in lines)


def _version(value: bool) -> None:
    if value:
        typer.echo(f"pkgtool {__version__}")
        raise typer.Exit(0)


@app.callback(epilog=examples(
    "pkgtool create my_robot --node talker:publisher --launch",
    "pkgtool lint --strict --style src/",
    "pkgtool doctor",
    "pkgtool COMMAND -h            # the options and examples of one command"))
def _root(
    version: Annotated[
        Optional[bool],
        typer.Option("--version", callback=_version, is_eager=True,
                     help="Print the version and exit."),
    ] = None,
) -> None:
    """Create, lint, check, test and grade ROS 2 Python (ament_python) packages."""


def _register(arguments: Sequence[str] = ()) -> None:
    """Attach each verb's command module (imported lazily inside the commands themselves).

    A run of one verb attaches that verb alone: typer reads the signature and type hints of
    every attached command on each start, ~80 ms for all of them. Help, completion and a
    mistyped verb (click suggests the near ones) see every verb.
    """
    import importlib

    chosen = arguments[0] if arguments else ""
    completing = COMPLETION_VARIABLE in os.environ
    verbs = (chosen,) if chosen in VERBS and not completing else VERBS
    for verb in verbs:
        importlib.import_module(f"pkgtool.cli_{verb}").register(app)


VERBS: tuple[str, ...] = ("lint", "create", "add", "test", "grade", "reference", "doctor")
"""Verbs with a ``pkgtool/cli_<verb>.py`` exposing ``register(app)``; add a verb when it works."""


def main() -> None:
    """Console-script entry point: run the command; Ctrl-C exits 130 with one line."""
    try:
        _register(sys.argv[1:])
        code = app(standalone_mode=False)  # typer turns KeyboardInterrupt into exit code 130
    except typer.TyperException as error:  # a usage error: typer's message and usage, exit 2
        error.show()  # type: ignore[attr-defined]  # every one raised is a click exception
        code = error.exit_code
    except (typer.Abort, KeyboardInterrupt):
        code = INTERRUPTED
    except BrokenPipeError:
        code = closed_pipe()
    finish(code if isinstance(code, int) else 0)
