"""The shipped robot_monitor rubric: the reference gets full marks, a wrong topic does not."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from tests.helpers import run_cli

pytestmark = [pytest.mark.ros, pytest.mark.colcon, pytest.mark.slow]

REPO = Path(__file__).resolve().parents[2]
REFERENCE = REPO / "reference_packages" / "robot_monitor"
RUBRIC = REPO / "docs" / "rubrics" / "robot_monitor" / "rubric.toml"


def test_reference_gets_full_marks_and_a_wrong_topic_loses_instructor_points(
        tmp_path: Path) -> None:
    if not (REFERENCE / "package.xml").is_file():
        pytest.skip("reference_packages/robot_monitor is not there yet")
    wrong = tmp_path / "wrong_topic"
    shutil.copytree(REFERENCE, wrong, ignore=shutil.ignore_patterns("__pycache__"))
    node = wrong / "robot_monitor" / "battery_monitor.py"
    node.write_text(node.read_text().replace("'/battery/voltage'", "'/battery'"))
    result = run_cli("grade", str(REFERENCE), str(wrong), "--rubric", str(RUBRIC), "--jobs", "2",
                     "--format", "json", cwd=tmp_path)
    assert result.exit_code == 0, result.output
    reference, broken = json.loads(result.stdout)["submissions"]
    assert reference["score"] == reference["max_score"] == 20, json.dumps(reference, indent=1)
    hidden = broken["criteria"][-1]
    assert hidden["kind"] == "hidden" and hidden["score"] < hidden["max_score"]
    assert "test_publishes_a_draining_voltage_on_battery_voltage" in "\n".join(hidden["feedback"])
    static = [c for c in broken["criteria"] if c["kind"] in ("build", "lint", "style")]
    assert all(c["passed"] for c in static), "the wrong topic is only found by running it"
