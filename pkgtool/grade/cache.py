"""Regrading cache (``pkgtool grade --cache DIR``): only what changed is graded again.

Each criterion's result is stored under the submission's digest (its content, not its label)
and the criterion's digest: the criterion's settings, its hidden-test folder's content, the
rubric-wide settings (graded package, limits) and the pkgtool version. A rerun reuses every
stored result; when criteria changed, one sandboxed job grades only those. Results of a job
that failed inside pkgtool (``internal error``) are never stored.
"""

from __future__ import annotations

import hashlib
import json
import os
import tempfile
import time
from pathlib import Path

from pkgtool import __version__
from pkgtool.grade.grader import grade_submission
from pkgtool.grade.results import CriterionResult, SubmissionResult
from pkgtool.grade.rubric import Criterion, Rubric
from pkgtool.grade.sources import tree_digest
from pkgtool.records import asdict, fields, replace


def criterion_digest(criterion: Criterion, rubric: Rubric) -> str:
    """SHA-256 of everything that decides ``criterion``'s result besides the submission."""
    settings = {f.name: getattr(criterion, f.name) for f in fields(criterion)}
    if criterion.path is not None:
        settings["path"] = tree_digest(criterion.path)
    shared = {"package": rubric.package, "limits": asdict(rubric.limits),
              "test_timeout": rubric.test_timeout, "pkgtool": __version__}
    text = json.dumps([settings, shared], sort_keys=True, default=str)
    return hashlib.sha256(text.encode()).hexdigest()


def _entry(folder: Path, submission: str, criterion: str) -> Path:
    return folder / submission[:2] / f"{submission}-{criterion}.json"


def _load(path: Path) -> dict | None:  # type: ignore[type-arg]
    try:
        return json.loads(path.read_text(encoding="utf-8"))  # type: ignore[no-any-return]
    except (OSError, ValueError):
        return None


def _store(path: Path, data: dict) -> None:  # type: ignore[type-arg]
    """Write atomically: a reader never sees half an entry."""
    path.parent.mkdir(parents=True, exist_ok=True)
    handle, temporary = tempfile.mkstemp(dir=path.parent, suffix=".tmp")
    with os.fdopen(handle, "w", encoding="utf-8") as out:
        json.dump(data, out)
    os.replace(temporary, path)


def grade_cached(path: Path, rubric: Rubric, *, folder: Path, label: str | None = None,
                 mode: str | None = None) -> SubmissionResult:
    """Grade ``path`` as :func:`grade_submission` does, reusing results stored in ``folder``."""
    start = time.monotonic()
    submission = tree_digest(path) if path.exists() else "missing"
    keys = {c.name: criterion_digest(c, rubric) for c in rubric.criteria}
    stored = {name: _load(_entry(folder, submission, key)) for name, key in keys.items()}
    missing = tuple(c for c in rubric.criteria if stored[c.name] is None)
    fresh = None
    if missing:
        fresh = grade_submission(path, replace(rubric, criteria=missing),
                                 label=label, mode=mode)
        for criterion in fresh.criteria:
            stored[criterion.name] = {"criterion": asdict(criterion),
                                      "package": fresh.package, "error": fresh.error,
                                      "isolation": fresh.isolation}
            if not (fresh.error or "").startswith("internal error"):
                _store(_entry(folder, submission, keys[criterion.name]),
                       stored[criterion.name])
    entries = [stored[c.name] for c in rubric.criteria]
    criteria = tuple(CriterionResult(**{**e["criterion"],  # type: ignore[index]
                                        "feedback": tuple(e["criterion"]["feedback"])})
                     for e in entries)
    first = entries[0]
    assert first is not None
    return SubmissionResult(
        label or path.name, str(path), round(sum(c.score for c in criteria), 2),
        rubric.max_score, criteria, first["package"], first["error"],
        fresh.isolation if fresh else first["isolation"], round(time.monotonic() - start, 2),
        fresh.unchanged if fresh else True)
