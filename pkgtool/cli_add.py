"""``pkgtool add node|launch|config|dependency``: adapters over :mod:`pkgtool.commands.add`."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Optional

import typer

from pkgtool.cli import examples
from pkgtool.commands import ExitCode

add_app = typer.Typer(
    name="add", no_args_is_help=True, rich_markup_mode=None,
    help="Add a node, launch file, parameter file or dependency to an existing package. "
    "Existing files are edited in place, every other byte kept; no file is overwritten.",
    epilog=examples("pkgtool add node scan_filter:subscriber:sensor_msgs/msg/LaserScan my_pkg",
                    "pkgtool add dependency numpy tf2_ros --path my_pkg",
                    "pkgtool add launch my_pkg --dry-run"))

_PATH = Annotated[Path, typer.Argument(help="The package folder.", metavar="PATH")]
_DRY = Annotated[bool, typer.Option("--dry-run", help="Print the changes as a unified diff; "
                                    "write nothing.")]


def _render(result, verb: str) -> None:  # type: ignore[no-untyped-def]
    if result.error:
        typer.echo(f"pkgtool add {verb}: {result.error}", err=True)
        raise typer.Exit(int(result.exit_code))
    for note in result.notes:
        typer.echo(f"note: {note}", err=True)
    if result.dry_run:
        typer.echo(result.diff or "Nothing to change.", nl=not result.diff)
    elif not (result.created or result.edited):
        typer.echo(f"Nothing to change in `{result.root}`.")
    else:
        typer.echo(f"Changed `{result.root}`:")
        for path in result.created:
            typer.echo(f"  new     {path}")
        for path in result.edited:
            typer.echo(f"  edited  {path}")
        typer.echo("Next: pkgtool lint, then colcon build and colcon test in its workspace.")
    raise typer.Exit(int(ExitCode.OK))


@add_app.command("node", epilog=examples(
    "pkgtool add node talker:publisher my_pkg",
    "pkgtool add node mover:action-client:nav2_msgs/action/NavigateToPose my_pkg --dry-run"))
def node(
    spec: Annotated[str, typer.Argument(
        metavar="NAME:KIND[:TYPE]", help="KIND: publisher, subscriber, service, client, "
        "action-server, action-client, timer; TYPE as in `pkgtool create --node`.")],
    path: _PATH = Path("."),
    launch_file: Annotated[Optional[str], typer.Option(
        metavar="FILE", help="The launch file (package-relative) to start the node from, "
        "when the package has several.", show_default=False)] = None,
    dry_run: _DRY = False,
) -> None:
    """Add a node: its module and test, console script, dependencies and launch entry."""
    from pkgtool.commands import add

    _render(add.node(path, spec, dry_run=dry_run, launch_file=launch_file), "node")


@add_app.command("launch", epilog=examples(
    "pkgtool add launch my_pkg", "pkgtool add launch my_pkg --name demo.launch.py"))
def launch(
    path: _PATH = Path("."),
    name: Annotated[Optional[str], typer.Option(
        metavar="FILE", help="File name under launch/ [<package>.launch.py].",
        show_default=False)] = None,
    dry_run: _DRY = False,
) -> None:
    """Add a launch file that starts the package's nodes, and install it."""
    from pkgtool.commands import add

    _render(add.launch(path, name=name, dry_run=dry_run), "launch")


@add_app.command("config", epilog=examples("pkgtool add config my_pkg"))
def config(path: _PATH = Path("."), dry_run: _DRY = False) -> None:
    """Add config/params.yaml with the parameters the nodes declare, and install it."""
    from pkgtool.commands import add

    _render(add.config(path, dry_run=dry_run), "config")


@add_app.command("dependency", epilog=examples(
    "pkgtool add dependency sensor_msgs numpy --path my_pkg",
    "pkgtool add dependency python3-pytest --test --path my_pkg"))
def dependency(
    names: Annotated[list[str], typer.Argument(
        metavar="NAME...", help="ROS packages (sensor_msgs), Python modules (numpy, mapped to "
        "their rosdep key) or rosdep keys (python3-numpy).")],
    path: Annotated[Path, typer.Option(help="The package folder.", metavar="DIR")] = Path("."),
    test: Annotated[bool, typer.Option("--test", help="Needed by the tests only "
                                       "(<test_depend>).")] = False,
    dry_run: _DRY = False,
) -> None:
    """Declare dependencies in package.xml with the right tag and rosdep key."""
    from pkgtool.commands import add

    _render(add.dependency(path, tuple(names), test=test, dry_run=dry_run), "dependency")


def register(app: typer.Typer) -> None:
    """Attach ``add`` to the root app."""
    app.add_typer(add_app)
