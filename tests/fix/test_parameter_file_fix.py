"""DAT008's fix: a misspelled ``ros__parameters`` key is renamed, nothing else in the file."""

from __future__ import annotations

from pathlib import Path

from pkgtool.commands.lint import LintOptions, run
from tests.helpers import correct_package_files, write_tree

BEFORE = """\
talker:
  "ros_parameters":   # how fast
    rate: 1
/**:
  ros_params: {x: 2}
listener:
  ros__parameters:
    topic: chatter
  stray: 3
"""

AFTER = BEFORE.replace('"ros_parameters"', '"ros__parameters"').replace(
    "ros_params:", "ros__parameters:")


def _fix(root: Path) -> list[str]:
    options = LintOptions(isolated=True, fix=True, select=("DAT008",))
    return [f.message for f in run([str(root)], options=options).findings]


def test_misspelled_keys_are_renamed_and_the_rest_is_left_to_the_user(tmp_path: Path) -> None:
    root = tmp_path / "pkg"
    write_tree(root, {**correct_package_files("pkg"), "config/params.yaml": BEFORE})
    left = _fix(root)
    assert (root / "config" / "params.yaml").read_text() == AFTER
    assert left == ["`stray` is beside `ros__parameters`, not inside it"], left
    assert _fix(root) == left and (root / "config" / "params.yaml").read_text() == AFTER


def test_a_near_miss_in_other_yaml_is_left_alone(tmp_path: Path) -> None:
    """A file no launch file passes, with a scalar above the near miss, is not renamed."""
    text = "model: x1\nbase:\n  ros_parameters:\n    wheel_radius: 0.1\n"
    root = tmp_path / "pkg"
    write_tree(root, {**correct_package_files("pkg"), "config/robot.yaml": text})
    assert _fix(root) == []
    assert (root / "config" / "robot.yaml").read_text() == text
