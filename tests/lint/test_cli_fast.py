"""The fast start of ``pkgtool lint`` reads command lines exactly as typer does, or not at all.

Typer's command is run with :func:`pkgtool.cli_lint_run.lint_call` replaced by a recorder; the
keyword arguments it records must equal :func:`pkgtool.cli_fast.parse_lint`'s. Where typer
rejects the command line, the fast start must hand it to typer (None).
"""

from __future__ import annotations

import inspect
import subprocess
import sys
from pathlib import Path
from typing import Any, Optional

import pytest

from pkgtool import cli_lint
from pkgtool.cli_fast import parse_lint
from pkgtool.cli_lint_run import lint_call
from tests.helpers import run_cli

COMMAND_LINES = [
    [], ["src"], ["a", "b"], ["src", "--fix", "other"], ["--", "-odd", "--fix"], ["-"],
    ["--format", "json"], ["--format=sarif"], ["-f", "junit"], ["-fgithub"],
    ["--format", "json", "--format", "text"], ["-o", "report.txt"], ["--output=r.json"],
    ["-or.txt"], ["--select", "MAN,DEP", "--select", "SYN"], ["--select=MAN"],
    ["--ignore", "MAN017", "--extend-select", "STY"], ["--select", "--fix"], ["--style"],
    ["--strict"], ["--no-strict"], ["--strict", "--no-strict"], ["--exit-zero"], ["-q"],
    ["--quiet"], ["--isolated"], ["--fix", "--unsafe-fixes"], ["--diff"], ["--no-cache"],
    ["--list-rules", "-f", "json"], ["--rosdistro", "humble"], ["--rosdistro="],
    ["--cache-dir", "/tmp/cache"], ["--explain", "MAN003"],
    ["ws/src", "--strict", "--style", "-f", "sarif", "-o", "out.sarif", "--no-cache"],
]
"""Command lines both parsers read."""
REJECTED = [
    ["--selct", "MAN"], ["--quiet=1"], ["--format"], ["-f", "xml"], ["-f", "JSON"],
    ["-o", "."], ["-x"], ["--strict=yes"],
]
"""Command lines typer rejects: the fast start leaves them to typer."""
LEFT_TO_TYPER = [["-h"], ["--help"], ["-qf", "json"], ["-qo", "r.txt"], ["--output="]]
"""Command lines typer reads (help, clusters of short options, an empty output file name) that
the fast start does not."""


def _typer_call(arguments: list[str], cwd: Path, monkeypatch: pytest.MonkeyPatch
                ) -> Optional[dict[str, Any]]:
    """The keyword arguments typer's ``lint`` passes on, None when it stops with an error."""
    recorded: list[dict[str, Any]] = []

    def record(*args: Any) -> int:
        recorded.append(dict(inspect.signature(lint_call).bind(*args).arguments))
        return 0

    monkeypatch.setattr(cli_lint, "lint_call", record)
    result = run_cli("lint", *arguments, cwd=cwd)
    assert result.exit_code in (0, 2), result.output
    return recorded[0] if recorded else None


def _without_defaults(call: dict[str, Any]) -> dict[str, Any]:
    defaults = {name: parameter.default
                for name, parameter in inspect.signature(lint_call).parameters.items()}
    return {name: value for name, value in call.items() if value != defaults[name]}


@pytest.mark.parametrize("arguments", COMMAND_LINES, ids=" ".join)
def test_fast_start_reads_what_typer_reads(arguments: list[str], tmp_path: Path,
                                           monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    by_typer = _typer_call(arguments, tmp_path, monkeypatch)
    assert by_typer is not None
    fast = parse_lint(arguments)
    assert fast is not None
    assert _without_defaults(fast) == _without_defaults(by_typer)


@pytest.mark.parametrize("arguments", REJECTED, ids=" ".join)
def test_what_typer_rejects_goes_to_typer(arguments: list[str], tmp_path: Path,
                                          monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    assert _typer_call(arguments, tmp_path, monkeypatch) is None
    assert parse_lint(arguments) is None


@pytest.mark.parametrize("arguments", LEFT_TO_TYPER, ids=" ".join)
def test_help_and_clusters_go_to_typer(arguments: list[str]) -> None:
    assert parse_lint(arguments) is None


def test_every_option_of_the_command_is_read() -> None:
    """An option added to ``cli_lint.lint`` needs a line in the fast start's tables."""
    import typer.main

    from pkgtool import cli_fast

    command = typer.main.get_command_from_info(
        typer.models.CommandInfo(name="lint", callback=cli_lint.lint),
        pretty_exceptions_short=True, rich_markup_mode=None)
    known = {*cli_fast._FLAGS, *cli_fast._VALUES, *cli_fast._LISTS, "-h", "--help"}
    options = {name for parameter in command.params
               for name in (*parameter.opts, *parameter.secondary_opts) if name.startswith("-")}
    assert options - known == set()


def test_the_console_script_starts_lint_without_typer(tmp_path: Path) -> None:
    probe = ("import atexit, sys; sys.argv = ['pkgtool', 'lint', '--no-cache', '-q', '.'];\n"
             "atexit.register(lambda: print('typer' in sys.modules))\n"
             "from pkgtool import cli_fast\n"
             "cli_fast.main()")
    done = subprocess.run([sys.executable, "-c", probe], cwd=tmp_path, capture_output=True,
                          text=True, timeout=60, check=True)
    assert done.stdout.split()[-1:] == ["False"], done.stderr
