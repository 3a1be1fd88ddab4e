"""The body of ``pkgtool lint``, free of typer: options in, report out, exit code back.

Both ways into ``lint`` call :func:`lint_call` with the same keyword arguments: typer's command
(:mod:`pkgtool.cli_lint`, which gives ``--help``, completion and usage errors) and the fast start
(:mod:`pkgtool.cli_fast`, which parses the common command lines without loading typer).
"""

from __future__ import annotations

import gc
import os
import sys
from collections.abc import Callable
from enum import Enum
from pathlib import Path
from typing import TYPE_CHECKING, Optional

from pkgtool.cli_output import emit
from pkgtool.commands import ExitCode

if TYPE_CHECKING:
    from pkgtool.cache import Shown
    from pkgtool.cache.replay import Witness
    from pkgtool.commands.lint import LintOptions, LintResult
    from pkgtool.commands.warm_worker import WarmWorker

STYLE_FAMILIES = ("STY", "CPY")
"""What ``--style`` adds to the selection."""
LINT_GC_THRESHOLDS = (50_000, 20, 100)
"""A lint run makes millions of short-lived syntax-tree objects and almost no reference cycles
(refcounting frees them): Python's default thresholds (700, 10, 10) collected all the time for
nothing, ~15% of a cold run (measured on 50 packages: 1.45 s CPU -> 1.17 s; one package
176 ms -> 157 ms)."""


WARM_WORKER_ENTRIES = 1000
"""A run whose record lists fewer folders and files than this (~40 packages, with pkgtool's own
~400) starts no warm worker: examining the cache takes too little time to hide the worker's
imports behind (measured on one package: ~5 ms slower when nothing changed, ~9 ms faster after
an edit; on 500 packages, ~130 ms faster after an edit). A record an older pkgtool wrote does
not say, and counts as large."""


class Format(str, Enum):
    """Report formats (see ``pkgtool.report``)."""

    TEXT = "text"
    JSON = "json"
    SARIF = "sarif"
    GITHUB = "github"
    JUNIT = "junit"


def lint_call(paths: Optional[list[str]] = None, fmt: Format = Format.TEXT,
              output: Optional[Path] = None, select: Optional[list[str]] = None,
              ignore: Optional[list[str]] = None, extend_select: Optional[list[str]] = None,
              style: bool = False, strict: Optional[bool] = None, exit_zero: bool = False,
              quiet: bool = False, isolated: bool = False, rosdistro: Optional[str] = None,
              fix: bool = False, diff: bool = False, unsafe_fixes: bool = False,
              no_cache: bool = False, cache_dir: Optional[str] = None,
              explain: Optional[str] = None, list_rules: bool = False) -> int:
    """Run ``pkgtool lint`` with the parsed command line; returns the exit code.

    A bug in pkgtool is reported with its traceback and exit code 3, not a bare traceback.
    """
    gc.set_threshold(*LINT_GC_THRESHOLDS)  # before the imports: they make objects too
    witness = worker = None
    try:
        if not (no_cache or fix or diff or list_rules or explain is not None) and \
                all(os.path.isdir(path) for path in paths or ["."]):
            from pkgtool.cache import cache_folder, replay

            stamp = replay.stamp(
                {"paths": paths, "format": fmt.value, "output": output and str(output),
                 "select": select, "ignore": ignore, "extend_select": extend_select,
                 "style": style, "strict": strict, "exit_zero": exit_zero, "quiet": quiet,
                 "isolated": isolated, "rosdistro": rosdistro}, _colour(fmt, output))
            folder = cache_folder(cache_dir, Path.cwd())
            record = replay.recorded(folder, stamp)
            if record is None or not record.entries or record.entries >= WARM_WORKER_ENTRIES:
                worker = _warm_worker()
            found = replay.replayed(folder, record)
            if isinstance(found, replay.Shown):
                return _show(found, output)
            witness = replay.Witness(folder, stamp, found)
        from pkgtool.commands import lint as command

        options = command.LintOptions(
            _selectors(select) if select else None, _selectors(ignore),
            _selectors(extend_select) + (STYLE_FAMILIES if style else ()), strict, exit_zero,
            quiet, isolated, rosdistro, fix, diff, unsafe_fixes, cache=not no_cache,
            cache_dir=cache_dir)
        try:
            if explain is not None or list_rules:
                return _show_rules(explain, fmt, output)
            return _lint(paths or [], options, fmt, output, witness, worker)
        except BrokenPipeError:
            raise  # the reader stopped early: no bug (the entry point exits quietly)
        except Exception as error:  # noqa: BLE001 - a bug in pkgtool: exit 3, no bare traceback
            import traceback

            say(f"Internal error: {type(error).__name__}: {error}. Please report this pkgtool "
                f"bug with the details below.\n{traceback.format_exc()}")
            return int(ExitCode.INTERNAL)
    finally:
        if worker is not None:
            worker.close()


def _warm_worker() -> Optional[WarmWorker]:
    """A :mod:`warm worker <pkgtool.commands.warm_worker>` importing the linter while the run
    examines the cache (stopped as soon as the cache answers for everything)."""
    from pkgtool.commands.warm_worker import start

    return start(_warm_up)


def _warm_up() -> list[Callable[[], None]]:
    from pkgtool.commands.lint import warm_up

    return warm_up()


def say(*messages: str) -> None:
    """Messages to stderr; they may quote a package's paths and text, so made safe first."""
    if not messages:
        return
    from pkgtool.report.untrusted import block

    for message in messages:
        sys.stderr.write(f"pkgtool lint: {block(message)}\n")


def _selectors(values: Optional[list[str]]) -> tuple[str, ...]:
    return tuple(s.strip() for value in values or () for s in value.split(",") if s.strip())


def _colour(fmt: Format, output: Optional[Path]) -> bool:
    return (fmt is Format.TEXT and output is None and sys.stdout.isatty()
            and not os.environ.get("NO_COLOR"))


def _lint(paths: list[str], options: LintOptions, fmt: Format, output: Optional[Path],
          witness: Optional[Witness], worker: Optional[WarmWorker]) -> int:
    from pkgtool.cache import Shown
    from pkgtool.commands.lint import run

    result = run(paths, options=options, witness=witness, worker=worker)
    if result.exit_code is ExitCode.USAGE:
        say(*result.notes, *result.errors)
        return int(result.exit_code)
    messages = []
    if result.fixed:
        done = "would fix" if options.diff else "fixed"
        messages = [f"{done} {len(result.fixed)}:", *(f"  {title}" for title in result.fixed)]
    report = result.diff if options.diff else _report(result, fmt, output)
    shown = Shown(int(result.exit_code), report, [*messages, *result.notes, *result.errors])
    code = _show(shown, output)
    if witness is not None and result.exit_code in (ExitCode.OK, ExitCode.FINDINGS):
        witness.keep(shown)
    return code


def _show(shown: Shown, output: Optional[Path]) -> int:
    """Print (or write) the report, then the messages; the exit code."""
    emit(shown.report, output, "lint")
    say(*shown.messages)
    return shown.code


def _show_rules(explain: Optional[str], fmt: Format, output: Optional[Path]) -> int:
    """``--explain RULE`` or ``--list-rules``: print, and return the exit code."""
    from pkgtool.commands import lint as command

    shown = (command.explain(explain) if explain is not None
             else command.list_rules(as_json=fmt is Format.JSON))
    if shown.errors:
        say(*shown.errors)
    else:
        emit(shown.text, output, "lint")
    return int(shown.exit_code)


def _report(result: LintResult, fmt: Format, output: Optional[Path]) -> str:
    from pkgtool.report import ReportContext, render
    from pkgtool.rules.registry import load, load_all

    # SARIF describes every rule; the others only the rules that found something.
    rules = load_all() if fmt is Format.SARIF else load(f.code for f in result.findings)
    fixable: dict[str, bool] = {}
    if result.findings:
        from pkgtool.fix.registry import fixers

        fixable = {code: entry.safe for code, entry in fixers().items()}
    context = ReportContext(result.packages, rules, _colour(fmt, output), fixable)
    return render(fmt.value, result.findings, context=context)
