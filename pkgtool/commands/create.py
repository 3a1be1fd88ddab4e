"""``pkgtool create``: scaffold an ament_python package that builds, lints clean and tests green.

Nothing here prints: :func:`run` returns a frozen :class:`CreateResult` that the CLI renders.
"""

from __future__ import annotations

import getpass
import os
import subprocess
import time
from dataclasses import dataclass, replace
from pathlib import Path

from pkgtool.commands import ExitCode
from pkgtool.create import CreateError
from pkgtool.create.options import Request, validate
from pkgtool.create.writer import (Hook, check_destination, enclosing_package, tree,
                                   write_package)

__all__ = ["CreateResult", "Request", "defaults", "run"]


@dataclass(frozen=True, slots=True)
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
        epoch = os.environ.get("SOURCE_DATE_EPOCH", "")
        year = time.gmtime(int(epoch) if epoch.isdigit() else None).tm_year
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
