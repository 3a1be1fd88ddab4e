"""Where a command's report goes: stdout, or an ``--output`` file checked before any work.

Free of typer, so the fast start of ``pkgtool lint`` (:mod:`pkgtool.cli_fast`) can use it: a
write error says why on stderr and ends the process with the usage code (``SystemExit``).
"""

from __future__ import annotations

import os
import sys
from pathlib import Path
from typing import Optional

from pkgtool.commands import ExitCode


def emit(text: str, output: Optional[Path], verb: str) -> None:
    """Print ``text``, or write it to ``output``; a write error exits with the usage code."""
    if output is None:
        sys.stdout.write(text)
        return
    try:
        output.write_text(text, encoding="utf-8")
    except OSError as error:
        _usage_error(verb, f"Cannot write `{output}`: {error.strerror or error}. Choose another "
                     "--output file.")


def check_output(output: Optional[Path], verb: str) -> None:
    """Exit with the usage code before any work when ``output``'s folder does not exist."""
    folder = output.absolute().parent if output is not None else None
    if folder is not None and not folder.is_dir():
        _usage_error(verb, f"Cannot write `{output}`: the folder `{folder}` does not exist. "
                     "Create it or choose another --output file.")


def _usage_error(verb: str, message: str) -> None:
    sys.stderr.write(f"pkgtool {verb}: {message}\n")
    raise SystemExit(int(ExitCode.USAGE))


CLOSED_PIPE = 141
"""The exit code when whoever reads the report stops early (``pkgtool lint | head``): that
of a process SIGPIPE ends, as ``cat`` and ``grep`` exit then."""


def closed_pipe() -> int:
    """Point stdout at ``os.devnull`` after the reader closed the pipe (so that exiting does
    not fail flushing it again) and give :data:`CLOSED_PIPE`."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError):
        pass
    return CLOSED_PIPE
