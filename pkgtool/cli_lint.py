"""``pkgtool lint``: parse options, call :mod:`pkgtool.commands.lint`, render, exit.

Only typer and the standard library are imported here, so ``pkgtool --help`` stays fast.
"""

from __future__ import annotations

import os
import sys
from enum import Enum
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Optional

import typer

from pkgtool.cli import examples
from pkgtool.cli_output import emit
from pkgtool.commands import ExitCode

if TYPE_CHECKING:
    from pkgtool.commands.lint import LintOptions, LintResult

STYLE_FAMILIES = ("STY", "CPY")
"""What ``--style`` adds to the selection."""
_RULES_HELP = "Rule codes, families (MAN), code prefixes or names; comma-separated or repeated."


class Format(str, Enum):
    """Report formats (see ``pkgtool.report``)."""

    TEXT = "text"
    JSON = "json"
    SARIF = "sarif"
    GITHUB = "github"
    JUNIT = "junit"


def _selectors(values: Optional[list[str]]) -> tuple[str, ...]:
    return tuple(s.strip() for value in values or () for s in value.split(",") if s.strip())


def _fail(*messages: str, code: ExitCode) -> typer.Exit:
    _say(*messages)
    return typer.Exit(int(code))


def _say(*messages: str) -> None:
    """Messages to stderr; they may quote a package's paths and text, so made safe first."""
    from pkgtool.report.untrusted import block

    for message in messages:
        typer.echo(f"pkgtool lint: {block(message)}", err=True)


def _colour(fmt: Format, output: Optional[Path]) -> bool:
    return (fmt is Format.TEXT and output is None and sys.stdout.isatty()
            and not os.environ.get("NO_COLOR"))


def lint(
    paths: Annotated[Optional[list[str]], typer.Argument(
        help="Packages, workspaces or files inside packages (default: the current folder).",
        show_default=False, metavar="PATH...")] = None,
    fmt: Annotated[Format, typer.Option("--format", "-f", help="Report format.")] = Format.TEXT,
    output: Annotated[Optional[Path], typer.Option(
        "--output", "-o", help="Write the report to this file instead of stdout.",
        dir_okay=False, metavar="FILE")] = None,
    select: Annotated[Optional[list[str]], typer.Option(
        help="Run only these rules. " + _RULES_HELP, show_default=False, metavar="RULES")] = None,
    ignore: Annotated[Optional[list[str]], typer.Option(
        help="Do not run these rules. " + _RULES_HELP, show_default=False,
        metavar="RULES")] = None,
    extend_select: Annotated[Optional[list[str]], typer.Option(
        help="Run these rules too. " + _RULES_HELP, show_default=False, metavar="RULES")] = None,
    style: Annotated[bool, typer.Option(
        "--style", help="Also run ament's style checks: flake8, pydocstyle and copyright "
        "headers (the STY and CPY rules).")] = False,
    strict: Annotated[Optional[bool], typer.Option(
        "--strict/--no-strict", help="Warnings fail too (default: from configuration, else off).",
        show_default=False)] = None,
    exit_zero: Annotated[bool, typer.Option(
        "--exit-zero",
        help="Exit 0 even when findings fail (usage and internal errors still exit 2 and 3).",
    )] = False,
    quiet: Annotated[bool, typer.Option(
        "--quiet", "-q", help="Leave info findings out of the report (they never fail).")] = False,
    isolated: Annotated[bool, typer.Option(
        "--isolated", help="Ignore [tool.pkgtool] in pyproject.toml files.")] = False,
    rosdistro: Annotated[Optional[str], typer.Option(
        "--rosdistro", help="The ROS 2 distribution to check against: humble, jazzy, kilted or "
        "rolling (default: `rosdistro` in [tool.pkgtool], else jazzy).", show_default=False,
        metavar="NAME")] = None,
    fix: Annotated[bool, typer.Option(
        "--fix", help="Apply the safe fixes, then report what is left.")] = False,
    diff: Annotated[bool, typer.Option(
        "--diff", help="Print the fixes as a unified diff and write nothing (exit 1 when "
        "there is one).")] = False,
    unsafe_fixes: Annotated[bool, typer.Option(
        "--unsafe-fixes", help="With --fix or --diff, also apply fixes that may change "
        "behaviour (removing or renaming a dependency).")] = False,
    no_cache: Annotated[bool, typer.Option(
        "--no-cache", help="Neither read nor write the lint cache.")] = False,
    cache_dir: Annotated[Optional[str], typer.Option(
        "--cache-dir", help="Where the lint cache lives (default: $PKGTOOL_CACHE_DIR, else "
        ".pkgtool_cache in the project root: the nearest folder up with a pyproject.toml, else "
        "the current folder).", show_default=False, metavar="DIR")] = None,
    explain: Annotated[Optional[str], typer.Option(
        help="Print the documentation of a rule (code, name or family) and exit.",
        show_default=False, metavar="RULE")] = None,
    list_rules: Annotated[bool, typer.Option("--list-rules", help="List every rule and exit.")
                          ] = False,
) -> None:
    """Check ament_python packages statically: package.xml, setup.py, setup.cfg, imports, launch.

    Exit codes: 0 clean (warnings allowed unless --strict), 1 failing findings, 2 usage or
    input error, 3 internal error.
    """
    from pkgtool.commands import lint as command

    options = command.LintOptions(_selectors(select) if select else None, _selectors(ignore),
                                  _selectors(extend_select) + (STYLE_FAMILIES if style else ()),
                                  strict, exit_zero, quiet, isolated, rosdistro, fix, diff,
                                  unsafe_fixes, cache=not no_cache, cache_dir=cache_dir)
    try:
        if explain is not None or list_rules:
            _show_rules(explain, fmt, output)
        _lint(paths or [], options, fmt, output)
    except typer.Exit:
        raise
    except Exception as error:  # noqa: BLE001 - a bug in pkgtool: exit 3, not a bare traceback
        import traceback

        raise _fail(f"Internal error: {type(error).__name__}: {error}. Please report this "
                    f"pkgtool bug with the details below.\n{traceback.format_exc()}",
                    code=ExitCode.INTERNAL) from None


def _lint(paths: list[str], options: LintOptions, fmt: Format, output: Optional[Path]) -> None:
    from pkgtool.commands.lint import run

    result = run(paths, options=options)
    if result.exit_code is ExitCode.USAGE:
        raise _fail(*result.notes, *result.errors, code=result.exit_code)
    if options.diff:
        emit(result.diff, output, "lint")
    else:
        _report(result, fmt, output)
    if result.fixed:
        done = "would fix" if options.diff else "fixed"
        _say(f"{done} {len(result.fixed)}:", *(f"  {title}" for title in result.fixed))
    _say(*result.notes, *result.errors)
    raise typer.Exit(int(result.exit_code))


def _show_rules(explain: Optional[str], fmt: Format, output: Optional[Path]) -> None:
    """``--explain RULE`` or ``--list-rules``: print and exit."""
    from pkgtool.commands import lint as command

    shown = (command.explain(explain) if explain is not None
             else command.list_rules(as_json=fmt is Format.JSON))
    if shown.errors:
        raise _fail(*shown.errors, code=shown.exit_code)
    emit(shown.text, output, "lint")
    raise typer.Exit(int(shown.exit_code))


def _report(result: LintResult, fmt: Format, output: Optional[Path]) -> None:
    from pkgtool.report import ReportContext, render
    from pkgtool.rules.registry import load, load_all

    # SARIF describes every rule; the others only the rules that found something.
    rules = load_all() if fmt is Format.SARIF else load(f.code for f in result.findings)
    fixable: dict[str, bool] = {}
    if result.findings:
        from pkgtool.fix.registry import fixers

        fixable = {code: entry.safe for code, entry in fixers().items()}
    context = ReportContext(result.packages, rules, _colour(fmt, output), fixable)
    emit(render(fmt.value, result.findings, context=context), output, "lint")


def register(app: typer.Typer) -> None:
    """Attach ``lint`` to the root app."""
    app.command("lint", epilog=examples(
        "pkgtool lint                              # the package or workspace here",
        "pkgtool lint --strict --style src/my_robot",
        "pkgtool lint --fix                        # repair what is safe, report the rest",
        "pkgtool lint ws/src --format sarif -o lint.sarif",
        "pkgtool lint --explain MAN003"))(lint)
