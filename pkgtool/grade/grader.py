"""Grade one submission: unpack or copy it into a sandboxed job, score every criterion."""

from __future__ import annotations

import os
import time
import traceback
from contextlib import AbstractContextManager, nullcontext
from pathlib import Path

from pkgtool.grade.criteria import Job, evaluate_all
from pkgtool.grade.extract import SubmissionError
from pkgtool.safe_fs import UnsafeFile, remove_tree
from pkgtool.grade.results import CriterionResult, SubmissionResult
from pkgtool.grade.rubric import Rubric
from pkgtool.grade.runner import WorkspaceRunner
from pkgtool.grade.sandbox import Sandbox, sandbox
from pkgtool.grade.sources import (choose_target, copy_packages, find_packages, tree_digest,
                                   with_dependencies)
from pkgtool.grade.stage import stage
from pkgtool.model.package import load_package
from pkgtool.ros.domains import leased_domain


def grade_submission(path: Path, rubric: Rubric, label: str | None = None,
                     mode: str | None = None, *, domain_id: int | None = None
                     ) -> SubmissionResult:
    """Grade ``path`` (package, workspace or archive); never raises for a bad submission.

    ``domain_id`` is the job's ROS domain (default: one leased for the job from
    :mod:`pkgtool.ros.domains`).
    """
    label = label or path.name
    start = time.monotonic()
    before = _digest(path)
    package, error, criteria, isolation = None, None, (), ""
    try:
        with sandbox(rubric.limits, mode=mode) as box, _domain(domain_id) as domain:
            job = _prepare(path, rubric, box, domain)
            package = job.name
            criteria = evaluate_all(job)
            isolation = box.describe()
    except SubmissionError as problem:
        error = str(problem)
    except Exception as crash:  # noqa: BLE001 - one broken job must not stop the batch
        where = traceback.extract_tb(crash.__traceback__)[-1]
        error = (f"internal error while grading: {type(crash).__name__}: {crash} "
                 f"({Path(where.filename).name}:{where.lineno})")
    if error:
        criteria = not_graded(rubric, error)
    unchanged = _digest(path) == before
    return SubmissionResult(label, str(path), round(sum(c.score for c in criteria), 2),
                            rubric.max_score, criteria, package, error, isolation,
                            round(time.monotonic() - start, 2), unchanged)


def _domain(given: int | None) -> AbstractContextManager[int]:
    """The job's ROS domain: ``given``, else one leased for the job."""
    return nullcontext(given) if given is not None else leased_domain()


def not_graded(rubric: Rubric, error: str) -> tuple[CriterionResult, ...]:
    """Zero on every criterion, each saying why nothing was graded."""
    return tuple(CriterionResult(c.name, c.kind, 0.0, c.points, (f"Not graded: {error}",),
                                 visibility=c.visibility) for c in rubric.criteria)


def _digest(path: Path) -> str:
    try:
        return tree_digest(path) if os.path.lexists(path) else "missing"
    except (OSError, UnsafeFile) as error:
        return f"unreadable: {error}"


def _prepare(path: Path, rubric: Rubric, box: Sandbox, domain_id: int) -> Job:
    tree = stage(path, box)
    available = find_packages(tree)
    target = choose_target(available, rubric.package)
    copies = copy_packages(with_dependencies(target, available), box.workspace / "src")
    remove_tree(tree)
    runner = WorkspaceRunner(box, domain_id=domain_id)
    return Job(rubric, runner, load_package(copies[target.name]))
