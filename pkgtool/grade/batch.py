"""Grade many submissions, each in its own process and sandbox, ``jobs`` at a time."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from functools import partial
from pathlib import Path

from pkgtool.grade.extract import is_archive
from pkgtool.grade.grader import grade_submission, not_graded
from pkgtool.grade.jobs import Task, run_tasks
from pkgtool.grade.lms import lms_submission
from pkgtool.grade.results import SubmissionResult
from pkgtool.grade.rubric import Rubric

Item = tuple[str, Path]
"""A submission to grade: its label (the student, usually) and its path."""


def expand(paths: Sequence[Path], *, batch: bool) -> list[Item]:
    """Submissions named by ``paths``; with ``batch`` each is a folder of submissions.

    In a batch folder every visible sub-folder, archive and link is one submission, labelled
    with its name (the file name without the archive suffix), or by student for Moodle and
    Canvas downloads (:mod:`pkgtool.grade.lms`); a link is refused when graded. A label seen
    twice gets ``-2``, ``-3``...
    """
    if not batch:
        return [(_label(p), p) for p in paths]
    items: list[Item] = []
    for folder in paths:
        for entry in sorted(folder.iterdir()):
            wanted = entry.is_symlink() or entry.is_dir() or is_archive(entry)
            if wanted and not entry.name.startswith("."):
                items.append(lms_submission(entry) or (_label(entry), entry))
    return _unique(items)


def _unique(items: list[Item]) -> list[Item]:
    seen: dict[str, int] = {}
    unique = []
    for label, path in items:
        seen[label] = seen.get(label, 0) + 1
        unique.append((label if seen[label] == 1 else f"{label}-{seen[label]}", path))
    return unique


def _label(path: Path) -> str:
    name = path.name
    for suffix in (".tar.gz", ".tgz", ".tar", ".zip"):
        if name.lower().endswith(suffix) and len(name) > len(suffix):
            return name[: -len(suffix)]
    return name


def grade_all(items: Sequence[Item], rubric: Rubric, *, jobs: int = 1, mode: str | None = None,
              on_done: Callable[[SubmissionResult], None] | None = None,
              cache: Path | None = None) -> list[SubmissionResult]:
    """Grade ``items`` (in their order in the result); ``on_done`` hears of each as it ends.

    Each submission is graded in a process of its own (:mod:`pkgtool.grade.jobs`) under the
    deadline of :func:`deadline`. With ``cache`` (a folder), results stored there are reused
    (:mod:`pkgtool.grade.cache`).
    """
    tasks = [Task(_grade, (path, rubric, label, mode, cache), deadline(rubric),
                  partial(_failed, label, str(path), rubric), rubric.limits.memory_mb + 2048)
             for label, path in items]
    return run_tasks(tasks, jobs=jobs, on_done=on_done)


def _grade(path: Path, rubric: Rubric, label: str, mode: str | None,
           cache: Path | None) -> SubmissionResult:
    if cache is None:
        return grade_submission(path, rubric, label, mode)
    from pkgtool.grade.cache import grade_cached

    return grade_cached(path, rubric, folder=cache, label=label, mode=mode)


def deadline(rubric: Rubric) -> float:
    """Seconds one submission may take in all: every step at its limit, plus a margin."""
    steps = 2 + sum(1 for c in rubric.criteria if c.kind in ("tests", "hidden"))
    probes = sum(len(c.names) for c in rubric.criteria if c.kind == "executables")
    return steps * rubric.limits.timeout + probes * min(rubric.test_timeout,
                                                        rubric.limits.timeout) + 120


def _failed(label: str, path: str, rubric: Rubric, reason: str) -> SubmissionResult:
    error = f"not graded: {reason}"
    return SubmissionResult(label, path, 0.0, rubric.max_score, not_graded(rubric, error),
                            error=error)
