"""``pkgtool grade``: score submissions against a rubric, each in its own sandboxed job.

Nothing here prints: :func:`run` returns a frozen :class:`GradeResult`; ``on_done`` lets the
CLI show progress. Grading a bad submission is not an error (it scores what it earns); only
usage problems (no rubric, a bad rubric, missing paths) change the exit code.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Sequence
from pathlib import Path

from pkgtool.commands import ExitCode
from pkgtool.grade.results import SubmissionResult
from pkgtool.grade.rubric import Rubric
from pkgtool.records import record

__all__ = ["GradeResult", "export_gradescope", "init_rubric", "run"]


@record
class GradeResult:
    """Graded submissions in the order given, or ``errors`` (sentences) for a usage error."""

    exit_code: ExitCode
    results: tuple[SubmissionResult, ...] = ()
    rubric: Rubric | None = None
    errors: tuple[str, ...] = ()
    written: tuple[str, ...] = ()


def init_rubric(path: Path) -> GradeResult:
    """Write the commented example rubric to ``path`` (never over an existing file)."""
    from pkgtool.grade.init_rubric import write_example

    if path.exists():
        return GradeResult(ExitCode.USAGE, errors=(
            f"`{path}` already exists. Choose a new file name for the example rubric.",))
    try:
        written = write_example(path)
    except OSError as error:
        return GradeResult(ExitCode.USAGE, errors=(
            f"Cannot write `{path}`: {error.strerror or error}. Choose another folder.",))
    return GradeResult(ExitCode.OK, written=tuple(map(str, written)))


def export_gradescope(rubric: Path, output: Path) -> GradeResult:
    """Write the Gradescope autograder bundle for ``rubric`` to ``output``."""
    from pkgtool.grade.gradescope_bundle import BundleError, build

    try:
        written = build(rubric, output)
    except BundleError as error:
        return GradeResult(ExitCode.USAGE, errors=(str(error),))
    except OSError as error:
        return GradeResult(ExitCode.USAGE, errors=(
            f"Cannot write `{output}`: {error.strerror or error}. Choose another folder.",))
    return GradeResult(ExitCode.OK, written=tuple(written))


def run(submissions: Sequence[str], *, rubric: str, batch: bool = False, jobs: int = 1,
        cwd: Path | None = None, mode: str | None = None, cache: str | None = None,
        on_start: Callable[[int, Rubric], None] | None = None,
        on_done: Callable[[SubmissionResult], None] | None = None) -> GradeResult:
    """Grade ``submissions`` (with ``batch``: folders of them) against the ``rubric`` file.

    ``on_start`` hears how many submissions will be graded against which rubric, ``on_done``
    each result as its job ends. ``mode`` forces a sandbox mode (see
    :mod:`pkgtool.grade.jail`); the default is the strongest this machine allows. ``cache`` is
    a folder of stored results to reuse (:mod:`pkgtool.grade.cache`).
    """
    from pkgtool.grade.batch import expand, grade_all
    from pkgtool.grade.jail import mode_error
    from pkgtool.grade.rubric import RubricError, load_rubric

    unavailable = mode_error(mode)
    if unavailable:
        return GradeResult(ExitCode.USAGE, errors=(unavailable,))
    here = Path(os.path.abspath(cwd or Path.cwd()))
    try:
        loaded = load_rubric(here / rubric)
    except RubricError as error:
        return GradeResult(ExitCode.USAGE, errors=(str(error),))
    paths = [here / s for s in submissions]
    missing = [s for s, p in zip(submissions, paths) if not os.path.lexists(p)]
    if missing or not paths:
        return GradeResult(ExitCode.USAGE, rubric=loaded, errors=tuple(
            f"Submission `{s}` does not exist. Check the path." for s in missing) or (
            "Name at least one submission (a package, workspace or archive).",))
    not_folders = [s for s, p in zip(submissions, paths) if batch and not p.is_dir()]
    if not_folders:
        return GradeResult(ExitCode.USAGE, rubric=loaded, errors=tuple(
            f"With --batch, `{s}` must be a folder of submissions." for s in not_folders))
    items = expand(paths, batch=batch)
    if on_start:
        on_start(len(items), loaded)
    results = grade_all(items, loaded, jobs=max(1, jobs), mode=mode, on_done=on_done,
                        cache=here / cache if cache else None)
    return GradeResult(ExitCode.OK, tuple(results), loaded)
