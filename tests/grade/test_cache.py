"""``--cache DIR``: a rerun reuses stored results and grades only changed criteria."""

from __future__ import annotations

from pathlib import Path

import pytest

from pkgtool.grade import cache as cache_module
from pkgtool.grade.batch import grade_all
from pkgtool.grade.rubric import load_rubric
from tests.grade.synthetic import correct, write_submission

RUBRIC = """\
title = "cache"
package = "talker_pkg"

[[criteria]]
kind = "lint"
name = "deps"
points = 2
select = ["DEP"]
per_finding = 1.0

[[criteria]]
kind = "lint"
name = "entry points"
points = {points}
select = ["ENT"]
"""


def _rubric(tmp_path: Path, points: int):  # type: ignore[no-untyped-def]
    path = tmp_path / "rubric.toml"
    path.write_text(RUBRIC.format(points=points))
    return load_rubric(path)


def _grade_cached(items, rubric, store: Path):  # type: ignore[no-untyped-def]
    """What grade_all does with a cache, in this process (its jobs run in processes of their
    own, where the spy below is not installed)."""
    return [cache_module.grade_cached(path, rubric, folder=store, label=label, mode="none")
            for label, path in items]


def test_a_changed_criterion_alone_is_regraded(tmp_path: Path,
                                               monkeypatch: pytest.MonkeyPatch) -> None:
    good = write_submission(tmp_path / "alice" / "talker_pkg", correct())
    broken = correct()
    broken["setup.py"] = broken["setup.py"].replace("talker_pkg.talker:main", "talker_pkg.x:y")
    bad = write_submission(tmp_path / "bob" / "talker_pkg", broken)
    items = [("alice", good.parent), ("bob", bad.parent)]
    graded: list[tuple[str, tuple[str, ...]]] = []
    real = cache_module.grade_submission

    def spy(path, rubric, **options):  # type: ignore[no-untyped-def]
        graded.append((options["label"], tuple(c.name for c in rubric.criteria)))
        return real(path, rubric, **options)

    monkeypatch.setattr(cache_module, "grade_submission", spy)
    store = tmp_path / "cache"
    first = _grade_cached(items, _rubric(tmp_path, 3), store)
    assert graded == [("alice", ("deps", "entry points")), ("bob", ("deps", "entry points"))]
    assert [r.score for r in first] == [5.0, 2.0]
    graded.clear()
    again = _grade_cached(items, _rubric(tmp_path, 3), store)
    assert graded == [] and [r.criteria for r in again] == [r.criteria for r in first]
    changed = _grade_cached(items, _rubric(tmp_path, 4), store)
    assert graded == [("alice", ("entry points",)), ("bob", ("entry points",))]
    assert [r.score for r in changed] == [6.0, 2.0]
    assert [c.name for c in changed[1].criteria] == ["deps", "entry points"]
    assert changed[1].criteria[1].feedback == first[1].criteria[1].feedback
    graded.clear()
    (bad / "setup.py").write_text(correct()["setup.py"])
    (bad / "README.md").write_text("fixed")
    fixed = _grade_cached(items, _rubric(tmp_path, 4), store)
    assert graded == [("bob", ("deps", "entry points"))] and fixed[1].score == 6.0
    through_jobs = grade_all(items, _rubric(tmp_path, 4), cache=store, mode="none")
    assert [r.criteria for r in through_jobs] == [r.criteria for r in fixed]
    graded.clear()
    (bad / "README.md").unlink()
    same_as_alice = grade_all(items, _rubric(tmp_path, 4), cache=store, mode="none")
    assert graded == [], "the key is the content, not the student"
    assert same_as_alice[1].label == "bob" and same_as_alice[1].score == 6.0
