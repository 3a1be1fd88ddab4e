"""``pkgtool create``: scaffold an ament_python package that builds, lints clean and tests green.

Nothing here prints: :func:`run` returns a frozen :class:`CreateResult` that the CLI renders.
"""

from __future__ import annotations

import getpass
import subprocess
from pathlib import Path

from pkgtool.commands import ExitCode
from pkgtool.create import CreateError
from pkgtool.create.options import Plan, Request, validate
from pkgtool.create.writer import (Hook, check_destination, enclosing_package, tree,
                                   write_package)
from pkgtool.records import record, replace

__all__ = ["CreateResult", "Request", "defaults", "run"]


@record
class CreateResult:
    """What happened: the package folder, the files written and kept, or the error."""

    exit_code: ExitCode
    root: Path | None = None
    written: tuple[str, ...] = ()
    kept: tuple[str, ...] = ()
    tree: str = ""
    dry_run: bool = False
    error: str = ""
    warnings: tuple[str, ...] = ()


def _git_config(key: str) -> str:
    try:
        done = subprocess.run(["git", "config", "--get", key], capture_output=True, text=True,
                              timeout=5, check=False)
    except (OSError, subprocess.SubprocessError):
        return ""
    return done.stdout.strip() if done.returncode == 0 else ""


def defaults(request: Request, *, maintainer_name: str | None,
             maintainer_email: str | None, year: int | None) -> Request:
    """Fill what the user left out like ``ros2 pkg create`` does.

    Maintainer from ``git config user.name``/``user.email`` (else the login name and
    ``<name>@todo.todo``); the copyright year from SOURCE_DATE_EPOCH, else the current year.
    """
    name = maintainer_name or _git_config("user.name") or getpass.getuser()
    email = maintainer_email or _git_config("user.email") or f"{name.replace(' ', '_')}@todo.todo"
    if year is None:
        from pkgtool.create.pysource import copyright_year

        year = copyright_year()
    return replace(request, maintainer_name=name, maintainer_email=email, year=year)


def run(request: Request, *, dry_run: bool = False, force: bool = False,
        before_write: Hook | None = None) -> CreateResult:
    """Validate ``request``, render the package and write it (or only draw it: ``dry_run``)."""
    from pkgtool.create.render import render

    try:
        plan = validate(request)
        outer = enclosing_package(plan.destination)
        if outer is not None:
            raise CreateError(
                f"`{plan.destination}` is inside the package `{outer.name}` ({outer}): colcon "
                "does not look for packages inside packages. Create it beside that package, "
                f"e.g. with --destination-directory {outer.parent}.")
        files = render(plan)
        if force and all((plan.root / f).is_file() for f in ("package.xml", "setup.py")):
            return _into_package(plan, files, dry_run=dry_run, before_write=before_write)
        if dry_run:
            written, kept = check_destination(plan.root, files, force=force)
        else:
            written, kept = write_package(plan.root, files, force=force,
                                          before_write=before_write)
    except CreateError as error:
        return CreateResult(ExitCode.USAGE, error=str(error))
    except OSError as error:
        return CreateResult(ExitCode.USAGE, error=f"Cannot write `{error.filename or ''}`: "
                            f"{error.strerror or error}. Nothing was left behind; check the "
                            "destination's permissions and free space.")
    marks = dict.fromkeys(kept, "exists, kept")
    return CreateResult(ExitCode.OK, plan.root, tuple(written), tuple(kept),
                        tree(plan.name, list(files), marks), dry_run=dry_run,
                        warnings=plan.warnings)


def _into_package(plan: Plan, files: dict[str, str], *, dry_run: bool,
                  before_write: Hook | None) -> CreateResult:
    """``--force`` into an existing package: nodes, launch and config go through ``add``.

    They are registered (console script, dependencies, data_files, launch entry) by editing
    the existing files in place; the other missing files are added as usual.
    """
    from pkgtool.add.files import add_config, add_launch
    from pkgtool.add.node import add_node
    from pkgtool.add.target import open_target
    from pkgtool.create.render import node_files
    from pkgtool.edit.core import EditError

    try:
        target = open_target(plan.root)
        for spec in plan.nodes:
            add_node(target, spec, year=plan.year)
        if plan.config:
            add_config(target, year=plan.year)
        if plan.launch:
            add_launch(target, year=plan.year)
        changes = target.session.changes()
    except EditError as error:
        return CreateResult(ExitCode.USAGE, error=str(error))
    handled = {*node_files(plan), f"launch/{plan.name}.launch.py", "config/params.yaml"}
    rest = {path: text for path, text in files.items() if path not in handled}
    if dry_run:
        written, kept = check_destination(plan.root, rest, force=True)
    else:
        changes.write()
        written, kept = write_package(plan.root, rest, force=True, before_write=before_write)
    added = [c.path for c in changes.files if c.before is None]
    edited = [c.path for c in changes.files if c.before is not None]
    kept_all = sorted(set(kept) | (handled & set(files)) - set(added) - set(edited))
    marks = dict.fromkeys(kept_all, "exists, kept") | dict.fromkeys(edited, "edited")
    return CreateResult(ExitCode.OK, plan.root, tuple(sorted([*written, *added, *edited])),
                        tuple(kept_all), tree(plan.name, sorted({*files, *edited}), marks),
                        dry_run=dry_run, warnings=plan.warnings)
