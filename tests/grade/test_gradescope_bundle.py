"""The Gradescope bundle, built and run here as Gradescope would: setup.sh, then run_autograder.

One bundle for the robot_monitor rubric is built and set up once (into a scratch root through
``PKGTOOL_AUTOGRADER_ROOT``, with this machine's Python 3.11 and the warm uv cache); each test
then grades one submission with ``run_autograder`` and checks ``results.json`` against the
fields Gradescope documents.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path
from typing import Any

import pytest

from pkgtool.grade.gradescope_bundle import build, needed, requirements
from pkgtool.grade.rubric import load_rubric

pytestmark = [pytest.mark.ros, pytest.mark.colcon, pytest.mark.slow,
              pytest.mark.xdist_group("gradescope_bundle")]  # one set-up, one worker

REPO = Path(__file__).resolve().parents[2]
RUBRIC = REPO / "docs" / "rubrics" / "robot_monitor" / "rubric.toml"
REFERENCE = REPO / "reference_packages" / "robot_monitor"
VISIBILITIES = {"visible", "hidden", "after_due_date", "after_published"}


def _python311() -> str:
    base = Path(sys.base_prefix) / "bin" / "python3.11"
    return str(base) if base.exists() else shutil.which("python3.11") or sys.executable


@pytest.fixture(scope="module")
def autograder(tmp_path_factory: pytest.TempPathFactory) -> Path:
    root = tmp_path_factory.mktemp("autograder")
    bundle = root / "autograder.zip"
    build(RUBRIC, bundle)
    with zipfile.ZipFile(bundle) as archive:
        archive.extractall(root / "source")
    for script in ("setup.sh", "run_autograder"):
        (root / "source" / script).chmod(0o755)
    env = {**os.environ, "PKGTOOL_AUTOGRADER_ROOT": str(root), "PKGTOOL_PYTHON": _python311()}
    done = subprocess.run(["bash", str(root / "source" / "setup.sh")], cwd=root / "source",
                          env=env, capture_output=True, text=True, timeout=900)
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    shutil.copy(root / "source" / "run_autograder", root / "run_autograder")
    return root


def _grade(root: Path, submission: dict[str, str] | Path, **env: str) -> dict[str, Any]:
    target = root / "submission"
    shutil.rmtree(target, ignore_errors=True)
    if isinstance(submission, Path):
        shutil.copytree(submission, target / submission.name,
                        ignore=shutil.ignore_patterns("__pycache__"))
    else:
        for name, text in submission.items():
            (target / name).parent.mkdir(parents=True, exist_ok=True)
            (target / name).write_text(text)
    done = subprocess.run(["bash", str(root / "run_autograder")], cwd=root,
                          env={**os.environ, "PKGTOOL_AUTOGRADER_ROOT": str(root), **env},
                          capture_output=True, text=True, timeout=1200)
    assert done.returncode == 0, done.stderr[-3000:]
    results = json.loads((root / "results" / "results.json").read_text())
    _check_gradescope_fields(results)
    return results


def _check_gradescope_fields(results: dict[str, Any]) -> None:
    """The fields of Gradescope's results.json specification, with their types."""
    assert isinstance(results["score"], (int, float))
    assert set(results) <= {"score", "execution_time", "output", "stdout_visibility", "tests",
                            "visibility", "extra_data", "output_format", "leaderboard"}
    assert isinstance(results.get("output", ""), str)
    assert results.get("stdout_visibility", "hidden") in VISIBILITIES
    assert isinstance(results.get("execution_time", 0), (int, float))
    for test in results["tests"]:
        assert isinstance(test["name"], str) and test["name"]
        assert isinstance(test["score"], (int, float))
        assert isinstance(test["max_score"], (int, float)) and test["score"] <= test["max_score"]
        assert isinstance(test["output"], str)
        assert test["visibility"] in VISIBILITIES


def test_the_reference_package_gets_full_marks(autograder: Path) -> None:
    results = _grade(autograder, REFERENCE)
    rubric = load_rubric(RUBRIC)
    assert results["score"] == rubric.max_score, json.dumps(results, indent=1)[:3000]
    assert [t["name"] for t in results["tests"]] == [c.name for c in rubric.criteria]
    assert [t["max_score"] for t in results["tests"]] == [c.points for c in rubric.criteria]
    assert "\nSandbox: " in results["output"]  # which isolation held, for the instructor


def test_a_submission_that_is_not_a_package_scores_zero_with_the_reason(
        autograder: Path) -> None:
    results = _grade(autograder, {"README.md": "I did not finish.\n"})
    assert results["score"] == 0
    assert "Not graded:" in results["output"]


def test_a_grader_that_runs_past_the_limit_leaves_zero_and_the_reason(
        autograder: Path) -> None:
    results = _grade(autograder, REFERENCE, PKGTOOL_AUTOGRADER_TIMEOUT="3")
    assert results == {"score": 0, "output": results["output"], "tests": [],
                       "stdout_visibility": "visible"}
    assert "did not finish within 3 s" in results["output"]


def test_a_grader_that_crashes_leaves_zero_and_the_reason(autograder: Path) -> None:
    rubric = autograder / "source" / "rubric" / "rubric.toml"
    saved = rubric.read_bytes()
    rubric.write_text("this is not TOML [")
    try:
        results = _grade(autograder, REFERENCE)
    finally:
        rubric.write_bytes(saved)
    assert results["score"] == 0 and results["tests"] == []
    assert "exit status 2" in results["output"]


def test_the_bundle_is_reproducible_and_holds_what_gradescope_runs(tmp_path: Path) -> None:
    first, second = tmp_path / "a.zip", tmp_path / "b.zip"
    build(RUBRIC, first)
    build(RUBRIC, second)
    assert first.read_bytes() == second.read_bytes()
    with zipfile.ZipFile(first) as archive:
        names = archive.namelist()
        modes = {i.filename: i.external_attr >> 16 for i in archive.infolist()}
    assert {"setup.sh", "run_autograder", "rubric/rubric.toml", "requirements.txt"} <= set(names)
    assert modes["setup.sh"] & 0o111 and modes["run_autograder"] & 0o111
    assert [n for n in names if n.startswith("wheels/")] == [
        n for n in names if n.startswith("wheels/pkgtool_ros-")]


def test_requirements_are_the_locked_pins_grading_needs() -> None:
    lock = (REPO / "requirements" / "lock.txt").read_text(encoding="utf-8")
    pins = requirements(lock).splitlines()[1:]
    assert "ros-jazzy-rclpy==7.1.6" in pins and "colcon-core==0.21.3" in pins
    assert not [p for p in pins if p.split("==")[0] in ("selenium", "hypothesis", "jsonschema")]
    assert all(f"{pin}\n" in lock for pin in pins)
    assert {"ros-jazzy-rclpy", "flake8", "colcon-common-extensions"} <= needed()
