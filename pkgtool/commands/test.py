"""``pkgtool test``: build a package with colcon in a temporary sandboxed workspace, run its tests.

The package (and the sibling packages of its workspace it depends on) is copied into a
temporary workspace: the source tree is never written to. Nothing here prints: :func:`run`
returns a frozen :class:`TestResult` that the CLI renders.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from functools import partial
from pathlib import Path

from pkgtool.commands import ExitCode
from pkgtool.grade.sources import SourcePackage, find_packages, with_dependencies
from pkgtool.records import record
from pkgtool.testresults import PackageTests
from pkgtool.workspace import is_package

__all__ = ["TestResult", "run"]


@record
class TestResult:
    """Every tested package, the sandbox in force, or ``errors`` (sentences) for a usage error."""

    exit_code: ExitCode
    packages: tuple[PackageTests, ...] = ()
    isolation: str = ""
    errors: tuple[str, ...] = ()


def run(path: str, *, timeout: float = 600.0, test_timeout: float | None = None,
        cwd: Path | None = None, mode: str | None = None) -> TestResult:
    """Build and test the package at ``path``, or every package of the workspace there."""
    from pkgtool.grade.jail import mode_error

    unavailable = mode_error(mode)
    if unavailable:
        return TestResult(ExitCode.USAGE, errors=(unavailable,))
    folder = Path(os.path.abspath((cwd or Path.cwd()) / path))
    if not folder.is_dir():
        return TestResult(ExitCode.USAGE, errors=(
            f"`{path}` is not a folder. Name a package or a workspace folder.",))
    targets, available = _targets(folder)
    if not targets:
        return TestResult(ExitCode.USAGE, errors=(
            f"No package (a folder with `package.xml`) in `{path}`. Name a package folder.",))
    packages, isolation = _build_and_test(targets, available, timeout, test_timeout, mode)
    code = ExitCode.OK if all(p.ok for p in packages) else ExitCode.FINDINGS
    return TestResult(code, packages, isolation)


def _targets(folder: Path) -> tuple[list[SourcePackage], list[SourcePackage]]:
    """The packages to test, and those they may depend on (their workspace's ``src``)."""
    if not is_package(folder):
        found = find_packages(folder)
        return found, found
    workspace = next((p for p in folder.parents if p.name == "src"), None)
    available = find_packages(workspace) if workspace else []
    target = next((p for p in available if p.root == folder), None)
    if target is None:
        target = find_packages(folder)[0]
        available.append(target)
    return [target], available


def _build_and_test(targets: Sequence[SourcePackage], available: Sequence[SourcePackage],
                    timeout: float, test_timeout: float | None,
                    mode: str | None) -> tuple[tuple[PackageTests, ...], str]:
    from pkgtool.grade.jobs import Task, run_tasks

    needed = tuple({p.name: p for t in targets for p in with_dependencies(t, available)}
                   .values())
    names = tuple(t.name for t in targets)
    task = Task(build_and_test, (names, needed, timeout, test_timeout, mode),
                (len(names) + 1) * timeout + 120, partial(_failed, names))
    return run_tasks([task])[0]  # type: ignore[no-any-return]


def build_and_test(names: Sequence[str], needed: Sequence[SourcePackage], timeout: float,
                   test_timeout: float | None,
                   mode: str | None) -> tuple[tuple[PackageTests, ...], str]:
    """Copy ``needed`` into a sandbox, build ``names`` and test each (in a job process)."""
    from pkgtool.grade.extract import SubmissionError
    from pkgtool.grade.runner import WorkspaceRunner
    from pkgtool.grade.sandbox import Limits, sandbox
    from pkgtool.grade.sources import copy_packages
    from pkgtool.ros.domains import leased_domain

    with sandbox(Limits(timeout=timeout), mode=mode) as box, leased_domain() as domain_id:
        try:
            copy_packages(needed, box.workspace / "src")
        except SubmissionError as error:
            return _failed(names, f"cannot copy the packages: {error}")
        runner = WorkspaceRunner(box, domain_id=domain_id)
        build = runner.build(names)
        if not build.ok:
            failed = tuple(PackageTests(n, False, None, build.output, build.limit, build.seconds)
                           for n in names)
            return failed, box.describe()
        results = []
        for name in names:
            run, summary = runner.test(name, test_timeout=test_timeout)
            results.append(PackageTests(name, True, summary, run.output, run.limit, run.seconds))
        return tuple(results), box.describe()


def _failed(names: Sequence[str], reason: str) -> tuple[tuple[PackageTests, ...], str]:
    return tuple(PackageTests(n, False, None, reason) for n in names), ""
