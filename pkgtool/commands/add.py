"""``pkgtool add``: grow an existing ament_python package through the edit engine.

Nothing here prints: each function returns a frozen :class:`AddResult` that the CLI renders.
Every operation is computed completely in memory first; only then are the files written, all
or none (``dry_run`` writes nothing and carries the diff).
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from pkgtool.commands import ExitCode
from pkgtool.edit.core import EditError
from pkgtool.records import record

__all__ = ["AddResult", "config", "dependency", "launch", "node"]


@record
class AddResult:
    """What changed (or would): new and edited files, the diff, notes, or the refusal."""

    exit_code: ExitCode
    root: Path | None = None
    created: tuple[str, ...] = ()
    edited: tuple[str, ...] = ()
    diff: str = ""
    notes: tuple[str, ...] = ()
    dry_run: bool = False
    error: str = ""


def _run(path: Path, operation: Callable[..., object], *, dry_run: bool) -> AddResult:
    from pkgtool.add.target import open_target

    try:
        target = open_target(path)
        operation(target)
        changes = target.session.changes()
        if not dry_run:
            changes.write()
    except EditError as error:
        return AddResult(ExitCode.USAGE, error=str(error))
    except OSError as error:
        return AddResult(ExitCode.USAGE, error=f"Cannot write `{error.filename or path}`: "
                         f"{error.strerror or error}. Nothing was changed; check permissions "
                         "and free space.")
    created = tuple(c.path for c in changes.files if c.before is None)
    edited = tuple(c.path for c in changes.files if c.before is not None)
    label = "" if path == Path(".") else str(path)
    return AddResult(ExitCode.OK, path, created, edited, changes.diff(label), tuple(target.notes),
                     dry_run)


def node(path: Path, spec: str, *, dry_run: bool = False, year: int | None = None,
         launch_file: str | None = None) -> AddResult:
    """Add the node ``NAME:KIND[:TYPE]``: module, test, console script, dependencies, launch."""
    from pkgtool.add.node import add_node, parse_spec

    try:
        parsed = parse_spec(spec)
    except EditError as error:
        return AddResult(ExitCode.USAGE, error=str(error))
    return _run(path, lambda t: add_node(t, parsed, year=year, launch_file=launch_file),
                dry_run=dry_run)


def launch(path: Path, *, name: str | None = None, dry_run: bool = False,
           year: int | None = None) -> AddResult:
    """Add a launch file starting the package's nodes, installed and its packages declared."""
    from pkgtool.add.files import add_launch

    return _run(path, lambda t: add_launch(t, name=name, year=year), dry_run=dry_run)


def config(path: Path, *, dry_run: bool = False, year: int | None = None) -> AddResult:
    """Add config/params.yaml with the parameters the package's nodes declare, installed."""
    from pkgtool.add.files import add_config

    return _run(path, lambda t: add_config(t, year=year), dry_run=dry_run)


def dependency(path: Path, names: tuple[str, ...], *, test: bool = False,
               dry_run: bool = False) -> AddResult:
    """Declare ROS packages, Python modules (by rosdep key) or rosdep keys in package.xml."""
    from pkgtool.add.depends import declare, resolve

    if not names:
        return AddResult(ExitCode.USAGE, error="Name at least one dependency.")
    try:
        ros, python = resolve(names)
    except EditError as error:
        return AddResult(ExitCode.USAGE, error=str(error))
    if test:
        return _run(path, lambda t: declare(t, tests=ros | python), dry_run=dry_run)
    return _run(path, lambda t: declare(t, ros=ros, exec_only=python), dry_run=dry_run)
