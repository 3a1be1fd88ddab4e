"""The console-script entry point: common ``pkgtool lint`` command lines skip typer.

Loading typer and building the lint command from its signature take ~40-60 ms, a fifth of a
one-package lint run (pre-commit's case). :func:`parse_lint` reads the command lines that need
no help, completion or error message, and gives the keyword arguments typer would give
:func:`pkgtool.cli_lint_run.lint_call`; anything else (``--help``, a mistyped option, a value
typer rejects, other verbs) returns None and goes to typer, which owns every message. A test
compares the two parsers on many command lines.
"""

from __future__ import annotations

import gc
import os
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import Any, Optional

INTERRUPTED = 130
"""Exit code of a run stopped by Ctrl-C (128 + SIGINT, as shells report it)."""
COMPLETION_VARIABLE = "_{}_COMPLETE".format(
    os.path.basename(sys.argv[0]).replace("-", "_").replace(".", "_").upper())
"""Set by the shell when it asks for completions (click names it after the program)."""

_FLAGS: dict[str, tuple[str, bool]] = {
    "--style": ("style", True), "--strict": ("strict", True), "--no-strict": ("strict", False),
    "--exit-zero": ("exit_zero", True), "--quiet": ("quiet", True), "-q": ("quiet", True),
    "--isolated": ("isolated", True), "--fix": ("fix", True), "--diff": ("diff", True),
    "--unsafe-fixes": ("unsafe_fixes", True), "--no-cache": ("no_cache", True),
    "--list-rules": ("list_rules", True),
}
"""Options without a value: option -> (parameter, value)."""
_VALUES: dict[str, str] = {
    "--format": "fmt", "-f": "fmt", "--output": "output", "-o": "output",
    "--rosdistro": "rosdistro", "--cache-dir": "cache_dir", "--explain": "explain",
}
"""Options taking one value (the last one given wins): option -> parameter."""
_LISTS: dict[str, str] = {
    "--select": "select", "--ignore": "ignore", "--extend-select": "extend_select"}
"""Options that may be repeated: option -> parameter."""


def main() -> None:
    """Run ``pkgtool``: the fast start for a plain lint command line, else typer's app."""
    arguments = sys.argv[1:]
    call = None
    if arguments[:1] == ["lint"] and COMPLETION_VARIABLE not in os.environ:
        call = parse_lint(arguments[1:])
    if call is None:
        from pkgtool.cli import main as typer_main

        typer_main()
        return
    from pkgtool.cli_lint_run import lint_call

    try:
        code = lint_call(**call)
    except KeyboardInterrupt:
        code = INTERRUPTED
    except BrokenPipeError:
        from pkgtool.cli_output import closed_pipe

        code = closed_pipe()
    finish(code, at_once=True)


def finish(code: int, *, at_once: bool = False) -> None:
    """Exit with ``code``; after Ctrl-C, say that nothing was written.

    ``at_once`` (a lint run: every file it writes is closed by now) ends the process without
    tearing the interpreter down, which frees every module and object one by one (~10 ms, a
    tenth of a one-package run): the exit handlers run and the standard streams are flushed
    first, as a normal exit does.
    """
    if code == INTERRUPTED:
        sys.stderr.write("Interrupted: nothing was written\n")
    gc.freeze()  # exit frees what is left: the final collection would only walk it (~20 ms)
    if not at_once:
        sys.exit(code)
    import atexit

    atexit._run_exitfuncs()
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (OSError, ValueError):  # a closed pipe or stream: nothing more can be said
            pass
    os._exit(code)


def parse_lint(arguments: Sequence[str]) -> Optional[dict[str, Any]]:
    """The keyword arguments of ``lint_call`` for ``pkgtool lint ARGUMENTS``, as typer gives
    them; None when typer must read the command line (help, an error, a form not read here)."""
    call: dict[str, Any] = {}
    paths: list[str] = []
    pending = list(arguments)
    while pending:
        argument = pending.pop(0)
        if argument == "--":
            paths.extend(pending)
            break
        if not argument.startswith("-") or argument == "-":
            paths.append(argument)
            continue
        option, value = _split(argument)
        if option in _FLAGS and value is None:
            name, flag = _FLAGS[option]
            call[name] = flag
            continue
        if option not in _VALUES and option not in _LISTS:
            return None  # help, a typo, a cluster of short options: typer says what it is
        if value is None:
            if not pending:
                return None
            value = pending.pop(0)
        if option in _LISTS:
            call.setdefault(_LISTS[option], []).append(value)
        else:
            call[_VALUES[option]] = value
    if paths:
        call["paths"] = paths
    return _converted(call)


def _split(argument: str) -> tuple[str, Optional[str]]:
    """``--name=value`` and ``-fvalue`` -> (option, value); a bare option -> (option, None)."""
    if argument.startswith("--"):
        option, equals, value = argument.partition("=")
        return option, value if equals else None
    if len(argument) > 2 and argument[:2] in _VALUES:
        return argument[:2], argument[2:]
    return argument, None


def _converted(call: dict[str, Any]) -> Optional[dict[str, Any]]:
    """Typer's conversions of the values: the format to its enum, the output file to a path
    (a folder is typer's error); None when typer would reject a value."""
    from pkgtool.cli_lint_run import Format

    if "fmt" in call:
        if call["fmt"] not in {member.value for member in Format}:
            return None
        call["fmt"] = Format(call["fmt"])
    if "output" in call:
        output = Path(call["output"])
        if not call["output"] or output.is_dir():
            return None
        call["output"] = output
    return call
