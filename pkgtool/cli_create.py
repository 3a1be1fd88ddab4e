"""``pkgtool create``: parse options, call :mod:`pkgtool.commands.create`, render, exit.

Option names follow ``ros2 pkg create`` so habits carry over: the package name is the one
positional argument, and ``--dependencies a b c`` takes every word up to the next option (so
``--dependencies a b NAME`` leaves no NAME: put NAME first). Repeated options and comma lists
work too.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Optional

import typer
from typer.core import TyperCommand

from pkgtool.cli import examples
from pkgtool.commands import ExitCode

if TYPE_CHECKING:
    from pkgtool.commands.create import CreateResult

_NODE_HELP = ("A node to generate (repeatable). KIND: publisher, subscriber, service, client, "
              "action-server, action-client, timer; TYPE overrides --msg/--srv/--action for "
              "this node.")
_GREEDY = "--dependencies"
EXAMPLES = examples(
    "pkgtool create my_robot --node talker:publisher --node listener:subscriber --launch",
    "pkgtool create my_robot --dependencies rclpy sensor_msgs numpy --license MIT",
    "pkgtool create driver --node drive:publisher:geometry_msgs/msg/Twist --config",
    "pkgtool create my_robot --license '?'          # the licenses whose text ships",
    "pkgtool create my_robot --dry-run               # print the tree, write nothing")


def spread_dependencies(args: list[str]) -> list[str]:
    """``--dependencies a b --x`` -> ``--dependencies a --dependencies b --x`` (argparse's ``+``).

    Every word after ``--dependencies`` up to the next option is a dependency, as in
    ``ros2 pkg create``; ``--`` ends the options.
    """
    out: list[str] = []
    greedy = bare = False
    for index, arg in enumerate(args):
        if arg == "--":
            out += args[index:]
            break
        if greedy and not arg.startswith("-"):
            out += [_GREEDY, arg]
            bare = False
            continue
        if bare:  # `--dependencies` followed by an option: let click say it needs a value
            out.append(_GREEDY)
        greedy = arg == _GREEDY or arg.startswith(f"{_GREEDY}=")
        bare = arg == _GREEDY
        if not bare:
            out.append(arg)
    return out + ([_GREEDY] if bare else [])


class CreateCommand(TyperCommand):
    """``create`` with ``ros2 pkg create``'s greedy ``--dependencies``."""

    def parse_args(self, ctx: typer.Context, args: list[str]) -> list[str]:
        spread = spread_dependencies(args)
        try:
            return super().parse_args(ctx, spread)
        except typer.BadParameter as error:  # MissingParameter is one
            param = getattr(error, "param", None)
            if spread == args or param is None or param.name != "name":
                raise
            raise typer.BadParameter(
                "none is left: every word after --dependencies is a dependency, as in "
                "`ros2 pkg create`. Put the package name first: `pkgtool create NAME "
                "--dependencies rclpy std_msgs`.", ctx=ctx, param=param) from None


def create(
    ctx: typer.Context,
    name: Annotated[str, typer.Argument(
        help="The package name (REP 144: lower_snake_case).", metavar="NAME")],
    destination_directory: Annotated[Path, typer.Option(
        help="Folder to create the package in.", metavar="DIR")] = Path("."),
    build_type: Annotated[str, typer.Option(
        help="Only ament_python (accepted for ros2 pkg create habits).",
        metavar="TYPE")] = "ament_python",
    package_format: Annotated[int, typer.Option(
        "--package-format", "--package_format", help="package.xml format: 3 or 2.",
        metavar="N")] = 3,
    description: Annotated[Optional[str], typer.Option(
        help="The package description.", show_default=False, metavar="TEXT")] = None,
    license_: Annotated[str, typer.Option(
        "--license", metavar="ID", help="An SPDX id or expression, or free text (e.g. "
        "Proprietary); `?` lists the licenses whose text ships.")] = "Apache-2.0",
    spdx_header: Annotated[bool, typer.Option(
        "--spdx-header", help="Add an SPDX-License-Identifier line under each file's "
        "copyright line (the license notice stays, for ament_copyright).")] = False,
    maintainer_name: Annotated[Optional[str], typer.Option(
        help="Default: git config user.name, else your login name.", show_default=False,
        metavar="TEXT")] = None,
    maintainer_email: Annotated[Optional[str], typer.Option(
        help="Default: git config user.email, else <maintainer>@todo.todo.",
        show_default=False, metavar="EMAIL")] = None,
    dependencies: Annotated[Optional[list[str]], typer.Option(
        help="ROS packages, Python modules (numpy) or rosdep keys the package depends on: "
        "every word up to the next option, comma lists, repeatable.", show_default=False,
        metavar="DEP...")] = None,
    node_name: Annotated[Optional[str], typer.Option(
        help="A node to generate, like --node NAME:timer.", show_default=False,
        metavar="NAME")] = None,
    library_name: Annotated[Optional[str], typer.Option(
        help="A Python sub-package to generate.", show_default=False, metavar="NAME")] = None,
    node: Annotated[Optional[list[str]], typer.Option(
        help=_NODE_HELP, show_default=False, metavar="NAME:KIND[:TYPE]")] = None,
    msg: Annotated[Optional[str], typer.Option(
        help="Message type of publisher/subscriber nodes [std_msgs/msg/String].",
        show_default=False, metavar="TYPE")] = None,
    srv: Annotated[Optional[str], typer.Option(
        help="Service type of service/client nodes [std_srvs/srv/Trigger].",
        show_default=False, metavar="TYPE")] = None,
    action: Annotated[Optional[str], typer.Option(
        help="Action type of action nodes [test_msgs/action/Fibonacci].",
        show_default=False, metavar="TYPE")] = None,
    launch: Annotated[bool, typer.Option(
        "--launch", help="Add a launch file starting the nodes.")] = False,
    config: Annotated[bool, typer.Option(
        "--config", help="Add config/params.yaml with the nodes' parameters.")] = False,
    copyright_year: Annotated[Optional[int], typer.Option(
        help="Year in the copyright headers (default: SOURCE_DATE_EPOCH, else this year).",
        show_default=False, metavar="YEAR")] = None,
    dry_run: Annotated[bool, typer.Option(
        "--dry-run", help="Print the tree that would be written; write nothing.")] = False,
    force: Annotated[bool, typer.Option(
        "--force", help="Into an existing folder: add missing files, never replace any.")] = False,
) -> None:
    """Create an ament_python package that builds, lints clean and tests green.

    Exit codes: 0 created, 2 refused (bad name, node kind or interface type, an existing
    folder, a folder inside another package).
    """
    from pkgtool.commands import create as command

    if license_.strip() == "?":
        from pkgtool.create.license_choice import listing

        typer.echo(listing(), nl=False)
        raise typer.Exit(0)
    if ctx.args:
        _fail(f"Unexpected argument `{ctx.args[0]}`: give one package NAME; dependencies go "
              "after --dependencies.")
    if build_type != "ament_python":
        _fail(f"Build type `{build_type}` is not supported: pkgtool creates ament_python "
              "packages only.")
    request = command.Request(
        name=name, destination=destination_directory, description=description, license=license_,
        dependencies=_words(dependencies), node_name=node_name, library_name=library_name,
        package_format=package_format, nodes=tuple(node or ()), msg=msg, srv=srv,
        action=action, launch=launch, config=config, spdx_header=spdx_header)
    request = command.defaults(request, maintainer_name=maintainer_name,
                               maintainer_email=maintainer_email, year=copyright_year)
    _show(command.run(request, dry_run=dry_run, force=force))


def _words(values: Optional[list[str]]) -> tuple[str, ...]:
    return tuple(w for value in values or () for w in value.replace(",", " ").split())


def _show(result: CreateResult) -> None:
    for warning in result.warnings:
        typer.echo(f"pkgtool create: warning: {warning}", err=True)
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
    app.command("create", cls=CreateCommand, epilog=EXAMPLES,
                context_settings={"allow_extra_args": True})(create)
