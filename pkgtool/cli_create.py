"""``pkgtool create``: parse options, call :mod:`pkgtool.commands.create`, render, exit.

Option names follow ``ros2 pkg create`` so habits carry over; ``--dependencies a b c`` works as
there (extra words after it are more dependencies), and so do repeated or comma lists.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Optional

import typer

from pkgtool.commands import ExitCode

_NODE_HELP = ("A node to generate, as NAME:KIND[:TYPE] (repeatable). KIND: publisher, "
              "subscriber, service, client, action-server, action-client, timer; TYPE overrides "
              "--msg/--srv/--action for this node.")


def _words(values: Optional[list[str]]) -> tuple[str, ...]:
    return tuple(w for value in values or () for w in value.replace(",", " ").split())


def create(
    ctx: typer.Context,
    name: Annotated[str, typer.Argument(
        help="The package name (REP 144: lower_snake_case).", metavar="NAME")],
    destination_directory: Annotated[Path, typer.Option(
        help="Folder to create the package in.")] = Path("."),
    build_type: Annotated[str, typer.Option(
        help="Only ament_python (accepted for ros2 pkg create habits).")] = "ament_python",
    package_format: Annotated[int, typer.Option(help="package.xml format: 3 or 2.")] = 3,
    description: Annotated[Optional[str], typer.Option(
        help="The package description.", show_default=False)] = None,
    license_: Annotated[str, typer.Option(
        "--license", help="SPDX id: Apache-2.0, BSL-1.0, BSD-2-Clause, BSD-3-Clause, MIT, MIT-0, "
        "GPL-3.0-only, LGPL-3.0-only.")] = "Apache-2.0",
    maintainer_name: Annotated[Optional[str], typer.Option(
        help="Default: git config user.name, else your login name.", show_default=False)] = None,
    maintainer_email: Annotated[Optional[str], typer.Option(
        help="Default: git config user.email, else <maintainer>@todo.todo.",
        show_default=False)] = None,
    dependencies: Annotated[Optional[list[str]], typer.Option(
        help="ROS packages, Python modules (numpy) or rosdep keys the package depends on; "
        "space- or comma-separated, repeatable.",
        show_default=False)] = None,
    node_name: Annotated[Optional[str], typer.Option(
        help="A node to generate, like --node NAME:timer.", show_default=False)] = None,
    library_name: Annotated[Optional[str], typer.Option(
        help="A Python sub-package to generate.", show_default=False)] = None,
    node: Annotated[Optional[list[str]], typer.Option(
        help=_NODE_HELP, show_default=False)] = None,
    msg: Annotated[Optional[str], typer.Option(
        help="Message type of publisher/subscriber nodes [std_msgs/msg/String].",
        show_default=False)] = None,
    srv: Annotated[Optional[str], typer.Option(
        help="Service type of service/client nodes [std_srvs/srv/Trigger].",
        show_default=False)] = None,
    action: Annotated[Optional[str], typer.Option(
        help="Action type of action nodes [test_msgs/action/Fibonacci].",
        show_default=False)] = None,
    launch: Annotated[bool, typer.Option(
        "--launch", help="Add a launch file starting the nodes.")] = False,
    config: Annotated[bool, typer.Option(
        "--config", help="Add config/params.yaml with the nodes' parameters.")] = False,
    copyright_year: Annotated[Optional[int], typer.Option(
        help="Year in the copyright headers (default: SOURCE_DATE_EPOCH, else this year).",
        show_default=False)] = None,
    dry_run: Annotated[bool, typer.Option(
        "--dry-run", help="Print the tree that would be written; write nothing.")] = False,
    force: Annotated[bool, typer.Option(
        "--force", help="Into an existing folder: add missing files, never replace any.")] = False,
) -> None:
    """Create an ament_python package that builds, lints clean and tests green.

    Exit codes: 0 created, 2 refused (bad name, license, node kind, or an existing folder).
    """
    from pkgtool.commands import create as command

    if ctx.args and not dependencies:
        _fail(f"Unexpected argument `{ctx.args[0]}`: give one package NAME.")
    if build_type != "ament_python":
        _fail(f"Build type `{build_type}` is not supported: pkgtool creates ament_python "
              "packages only.")
    request = command.Request(
        name=name, destination=destination_directory, description=description, license=license_,
        dependencies=_words([*(dependencies or ()), *ctx.args]), node_name=node_name,
        library_name=library_name, package_format=package_format, nodes=tuple(node or ()),
        msg=msg, srv=srv, action=action, launch=launch, config=config)
    request = command.defaults(request, maintainer_name=maintainer_name,
                               maintainer_email=maintainer_email, year=copyright_year)
    result = command.run(request, dry_run=dry_run, force=force)
    if result.error:
        _fail(result.error, code=result.exit_code)
    verb = "Would create" if result.dry_run else "Created"
    typer.echo(f"{verb} `{result.root}` ({len(result.written)} files"
               + (f", {len(result.kept)} existing kept" if result.kept else "") + "):")
    typer.echo(result.tree, nl=False)
    if not result.dry_run:
        typer.echo("Next: pkgtool lint, then colcon build and colcon test in its workspace.")
    raise typer.Exit(int(result.exit_code))


def _fail(message: str, code: ExitCode = ExitCode.USAGE) -> None:
    typer.echo(f"pkgtool create: {message}", err=True)
    raise typer.Exit(int(code))


def register(app: typer.Typer) -> None:
    """Attach ``create`` to the root app."""
    app.command("create", context_settings={"allow_extra_args": True})(create)
