"""`pkgtool grade --batch --jobs 2` over synthetic submissions, each with one defect.

One batch grades them all (about a minute on 2 cores): each gets its expected score and
message, the bad ones do not disturb the good ones, and no submission changes on disk.
"""

from __future__ import annotations

import json
import uuid
from pathlib import Path
from typing import Any

import pytest

from pkgtool.grade.jail import jail_support
from pkgtool.grade.rubric import Rubric, load_rubric
from pkgtool.grade.sandbox import Limits, sandbox
from pkgtool.grade.sources import tree_digest
from tests.grade import synthetic
from tests.helpers import run_cli

pytestmark = [pytest.mark.ros, pytest.mark.colcon, pytest.mark.slow]

Batch = dict[str, Any]
Entry = dict[str, Any]
NAMES = ("correct", "cheater", "missing_entry_point", "undeclared_dependency", "build_failure",
         "failing_test", "infinite_loop", "writes_outside", "fork_bomb", "hangs_at_import")


@pytest.fixture(scope="module")
def batch(tmp_path_factory: pytest.TempPathFactory) -> Batch:
    root = tmp_path_factory.mktemp("grading")
    subs = root / "submissions"
    token = uuid.uuid4().hex[:10]
    markers = {"tmp": Path(f"/tmp/pkgtool-escape-{token}"),
               "root": Path(f"/root/pkgtool-escape-{token}")}
    with sandbox(Limits()) as box:
        bounded = box.bounds_processes  # the fork bomb runs only where processes are capped
    names = [n for n in NAMES if bounded or n != "fork_bomb"]
    for name, files in synthetic.variants({n: subs / n for n in NAMES}, markers).items():
        if name in names:
            synthetic.write_submission(subs / name, files)
    staging = root / "staging"
    synthetic.write_submission(staging / "talker_pkg", synthetic.correct())
    synthetic.tar_gz(subs / "correct_tgz.tar.gz", staging / "talker_pkg")
    (subs / "archive_in_folder").mkdir()  # as Gradescope and Moodle hand over an upload
    synthetic.tar_gz(subs / "archive_in_folder" / "upload.tar.gz", staging / "talker_pkg")
    synthetic.zip_with_traversal(subs / "zip_traversal.zip", staging / "talker_pkg")
    before = {p.name: tree_digest(p) for p in subs.iterdir()}
    (root / "rubric.toml").write_text(synthetic.RUBRIC.format(timeout=30,
                                                              hidden=synthetic.HIDDEN))
    result = run_cli("grade", "submissions", "--batch", "--rubric", "rubric.toml", "--jobs", "2",
                     "--format", "json", "--output", "report.json", cwd=root)
    assert result.exit_code == 0, result.output
    report = json.loads((root / "report.json").read_text())
    graded = {s["label"]: s for s in report["submissions"]}
    after = {p.name: tree_digest(p) for p in subs.iterdir()}
    return {"graded": graded, "before": before, "after": after, "markers": markers,
            "rubric": load_rubric(root / "rubric.toml"),
            "names": names, "escaped": [root / "escaped.txt", root / "submissions" /
                                        "escaped.txt", Path("/tmp/escaped.txt")]}


def _criterion(entry: Entry, kind: str) -> Entry:
    return next(c for c in entry["criteria"] if c["kind"] == kind)


def _feedback(entry: Entry, kind: str) -> str:
    return "\n".join(_criterion(entry, kind)["feedback"])


OWN_TESTS = 2
"""The tests of ``synthetic.correct()``; both pass. Variants add failing ones."""


def _points(batch: Batch, kind: str) -> float:
    """The points of the rubric's criterion of ``kind``."""
    rubric: Rubric = batch["rubric"]
    return next(c.points for c in rubric.criteria if c.kind == kind)


def _per_finding(batch: Batch) -> float:
    rubric: Rubric = batch["rubric"]
    return next(c.per_finding or 0.0 for c in rubric.criteria if c.kind == "lint")


def test_every_submission_is_graded_and_left_unchanged(batch: Batch) -> None:
    graded = batch["graded"]
    assert set(graded) == {*batch["names"], "correct_tgz", "archive_in_folder",
                           "zip_traversal"}
    assert batch["before"] == batch["after"]
    assert all(entry["unchanged"] for entry in graded.values())


@pytest.mark.parametrize("label", ["correct", "correct_tgz", "archive_in_folder"])
def test_a_correct_submission_gets_full_marks(batch: Batch, label: str) -> None:
    entry = batch["graded"][label]
    assert entry["score"] == entry["max_score"] == batch["rubric"].max_score, \
        json.dumps(entry, indent=1)
    expected = {"root": "namespaces: mount, net (loopback only), pid, ipc, uts, cgroup",
                "userns": "namespaces: user, mount, net (loopback only), pid, ipc, uts, cgroup",
                "none": "no namespaces"}[jail_support().mode]
    assert entry["isolation"].startswith(expected), entry["isolation"]


def test_a_conftest_or_setup_cfg_of_the_submission_cannot_touch_instructor_tests(
        batch: Batch) -> None:
    entry = batch["graded"]["cheater"]
    hidden = _criterion(entry, "hidden")
    assert hidden["score"] == 0 and "2 failed" in _feedback(entry, "hidden")


def test_missing_entry_point(batch: Batch) -> None:
    entry = batch["graded"]["missing_entry_point"]
    assert _criterion(entry, "executables")["score"] == 0
    assert "No module named 'talker_pkg.talker'" in _feedback(entry, "executables")
    lint = _points(batch, "lint") - _per_finding(batch)  # one finding: ENT002
    assert _criterion(entry, "lint")["score"] == lint and "ENT002" in _feedback(entry, "lint")
    assert entry["score"] == entry["max_score"] - _points(batch, "executables") - \
        _per_finding(batch)


def test_undeclared_dependency(batch: Batch) -> None:
    entry = batch["graded"]["undeclared_dependency"]
    assert "DEP001 `numpy` is imported" in _feedback(entry, "lint")
    assert "Declare what you import" in _feedback(entry, "lint")
    assert entry["score"] == entry["max_score"] - _per_finding(batch)  # one finding: DEP001


def test_build_failure(batch: Batch) -> None:
    entry = batch["graded"]["build_failure"]
    assert _criterion(entry, "build")["score"] == 0
    assert "missing.yaml" in _feedback(entry, "build")
    for kind in ("executables", "tests", "hidden"):
        assert "does not build" in _feedback(entry, kind)
    assert entry["score"] == _points(batch, "lint") + _points(batch, "style")  # static only


def test_failing_test(batch: Batch) -> None:
    entry = batch["graded"]["failing_test"]
    credit = round(_points(batch, "tests") * (OWN_TESTS - 1) / OWN_TESTS, 2)  # partial credit
    assert _criterion(entry, "tests")["score"] == credit
    assert "1 passed, 1 failed" in _feedback(entry, "tests")
    assert "FAILED talker_pkg.test.test_greet.test_greets_anyone" in _feedback(entry, "tests")
    assert entry["score"] == entry["max_score"] - _points(batch, "tests") + credit


def test_infinite_loop_in_a_test(batch: Batch) -> None:
    entry = batch["graded"]["infinite_loop"]
    looping = 1  # the variant adds one test that never ends
    assert _criterion(entry, "tests")["score"] == round(
        _points(batch, "tests") * OWN_TESTS / (OWN_TESTS + looping), 2)  # scores are in cents
    assert "Timeout (>5.0s)" in _feedback(entry, "tests")
    assert _criterion(entry, "hidden")["score"] == _points(batch, "hidden")


def test_a_module_that_hangs_when_imported_costs_its_executable_only(batch: Batch) -> None:
    entry = batch["graded"]["hangs_at_import"]
    assert _criterion(entry, "executables")["score"] == 0
    assert "`talker` did not finish loading (timed out after 5 s)" in _feedback(
        entry, "executables"), "the probe is bounded by test_timeout, not the step timeout"
    assert entry["score"] == entry["max_score"] - _points(batch, "executables")


def test_writing_outside_the_package_changes_nothing(batch: Batch) -> None:
    entry = batch["graded"]["writes_outside"]
    writers = 3  # the variant adds three tests that write outside the job
    # in a jail /tmp is the job's own: that write succeeds there and never reaches the machine
    jailed = jail_support().mode != "none"
    failing = writers - 1 if jailed else writers
    assert _criterion(entry, "tests")["score"] == round(
        _points(batch, "tests") * (OWN_TESTS + writers - failing) / (OWN_TESTS + writers), 2)
    feedback = _feedback(entry, "tests")
    assert feedback.count("FAILED talker_pkg.test.test_escape.") == failing, feedback
    assert ("test_escape.test_writes_to_tmp" in feedback) is not jailed, feedback
    assert not any(marker.exists() for marker in batch["markers"].values())


def test_a_fork_bomb_is_stopped_without_harm(batch: Batch) -> None:
    if "fork_bomb" not in batch["names"]:
        pytest.skip("no process limit can be enforced on this machine")
    entry = batch["graded"]["fork_bomb"]
    assert "too many processes (limit 64)" in _feedback(entry, "tests")
    assert _criterion(entry, "tests")["score"] < _points(batch, "tests")
    assert _criterion(entry, "hidden")["score"] == _points(batch, "hidden")


def test_a_zip_with_parent_paths_is_refused(batch: Batch) -> None:
    entry = batch["graded"]["zip_traversal"]
    assert entry["score"] == 0 and "points outside the submission" in entry["error"]
    assert not any(path.exists() for path in batch["escaped"])
