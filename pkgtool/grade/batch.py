"""Grade many submissions, each in its own process and sandbox, ``jobs`` at a time."""

from __future__ import annotations

import multiprocessing
from functools import partial
from collections.abc import Callable, Sequence
from concurrent.futures import Future, ProcessPoolExecutor, as_completed
from pathlib import Path

from pkgtool.grade.extract import is_archive
from pkgtool.grade.grader import grade_submission, not_graded
from pkgtool.grade.lms import lms_submission
from pkgtool.grade.results import SubmissionResult
from pkgtool.grade.rubric import Rubric

Item = tuple[str, Path]
"""A submission to grade: its label (the student, usually) and its path."""


def expand(paths: Sequence[Path], *, batch: bool) -> list[Item]:
    """Submissions named by ``paths``; with ``batch`` each is a folder of submissions.

    In a batch folder every visible sub-folder and archive is one submission, labelled with
    its name (the file name without the archive suffix), or by student for Moodle and Canvas
    downloads (:mod:`pkgtool.grade.lms`). A label seen twice gets ``-2``, ``-3``...
    """
    if not batch:
        return [(_label(p), p) for p in paths]
    items: list[Item] = []
    for folder in paths:
        for entry in sorted(folder.iterdir()):
            if not entry.name.startswith(".") and (entry.is_dir() or is_archive(entry)):
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

    With ``cache`` (a folder), results stored there are reused (:mod:`pkgtool.grade.cache`).
    """
    notify = on_done or (lambda _: None)
    grade: Callable[..., SubmissionResult] = grade_submission
    if cache is not None:
        from pkgtool.grade.cache import grade_cached

        grade = partial(grade_cached, folder=cache)
    if jobs <= 1 or len(items) <= 1:
        results = []
        for slot, (label, path) in enumerate(items):
            results.append(grade(path, rubric, label=label, mode=mode))
            notify(results[-1])
        return results
    done: dict[int, SubmissionResult] = {}
    context = multiprocessing.get_context("spawn")
    with ProcessPoolExecutor(max_workers=jobs, mp_context=context) as pool:
        futures: dict[Future[SubmissionResult], int] = {
            pool.submit(grade, path, rubric, label=label, mode=mode): slot
            for slot, (label, path) in enumerate(items)}
        for future in as_completed(futures):
            slot = futures[future]
            try:
                done[slot] = future.result()
            except Exception as crash:  # noqa: BLE001 - a dead worker fails its job only
                done[slot] = _crashed(items[slot], rubric, crash)
            notify(done[slot])
    return [done[slot] for slot in range(len(items))]


def _crashed(item: Item, rubric: Rubric, crash: Exception) -> SubmissionResult:
    error = f"internal error: the grading process died ({type(crash).__name__}: {crash})"
    return SubmissionResult(item[0], str(item[1]), 0.0, rubric.max_score,
                            not_graded(rubric, error), error=error)
