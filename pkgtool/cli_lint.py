"""``pkgtool lint``: typer's command line (help, completion, usage errors) over
:func:`pkgtool.cli_lint_run.lint_call`, which :mod:`pkgtool.cli_fast` also calls.

Only typer and the standard library are imported here, so ``pkgtool --help`` stays fast.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Optional

import typer

from pkgtool.cli import examples
from pkgtool.cli_lint_run import Format, lint_call

_RULES_HELP = "Rule codes, families (MAN), code prefixes or names; comma-separated or repeated."


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
    raise typer.Exit(lint_call(
        paths, fmt, output, select, ignore, extend_select, style, strict, exit_zero, quiet,
        isolated, rosdistro, fix, diff, unsafe_fixes, no_cache, cache_dir, explain, list_rules))


def register(app: typer.Typer) -> None:
    """Attach ``lint`` to the root app."""
    app.command("lint", epilog=examples(
        "pkgtool lint                              # the package or workspace here",
        "pkgtool lint --strict --style src/my_robot",
        "pkgtool lint --fix                        # repair what is safe, report the rest",
        "pkgtool lint ws/src --format sarif -o lint.sarif",
        "pkgtool lint --explain MAN003"))(lint)
