"""Rubric loading: strict checks with located messages, and the --init-rubric example."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from pkgtool.compat import tomllib
from pkgtool.grade.init_rubric import example_rubric, write_example
from pkgtool.grade.rubric import RubricError, load_rubric

REPO = Path(__file__).resolve().parents[2]


def _load(tmp_path: Path, text: str):  # type: ignore[no-untyped-def]
    (tmp_path / "tests").mkdir(exist_ok=True)
    path = tmp_path / "rubric.toml"
    path.write_text(text)
    return load_rubric(path)


def test_the_example_rubric_loads_and_keeps_its_comments(tmp_path: Path) -> None:
    written = write_example(tmp_path / "rubric.toml")
    text = (tmp_path / "rubric.toml").read_text()
    assert text.count("#") > 15, "the example explains itself"
    assert tomllib.loads(text)["criteria"][0]["kind"] == "build"
    rubric = load_rubric(tmp_path / "rubric.toml")
    kinds = [c.kind for c in rubric.criteria]
    assert kinds == ["build", "executables", "lint", "style", "tests", "hidden"]
    assert rubric.max_score == 14
    assert rubric.criteria[5].path == (tmp_path / "hidden_tests").resolve()
    assert tmp_path / "hidden_tests" / "test_hidden_example.py" in written
    assert all(len(line) <= 99 for line in example_rubric().splitlines())


def test_the_robot_monitor_rubric_loads() -> None:
    rubric = load_rubric(REPO / "docs" / "rubrics" / "robot_monitor" / "rubric.toml")
    assert rubric.package == "robot_monitor" and rubric.max_score == 20


def test_defaults(tmp_path: Path) -> None:
    rubric = _load(tmp_path, '[[criteria]]\nkind = "style"\npoints = 1\n')
    style = rubric.criteria[0]
    assert style.select == ("STY",) and style.per_finding is None
    assert style.name.startswith("Style")
    assert rubric.limits.timeout == 300 and rubric.test_timeout == 60


@pytest.mark.parametrize(("text", "message"), [
    ("", "add at least one"),
    ('[[criteria]]\nkind = "bake"\npoints = 1\n', "`kind` must be one of"),
    ('[[criteria]]\nkind = "build"\npoints = -1\n', "`points` must be a number"),
    ('[[criteria]]\nkind = "build"\npoints = 1\nselect = ["MAN"]\n', "unknown key `select`"),
    ('[[criteria]]\nkind = "lint"\npoints = 1\nselect = ["NOPE"]\n', "`NOPE` matches no"),
    ('[[criteria]]\nkind = "lint"\npoints = 1\n', "list rule codes"),
    ('[[criteria]]\nkind = "executables"\npoints = 1\n', "`names`"),
    ('[[criteria]]\nkind = "hidden"\npoints = 1\npath = "missing"\n', "does not exist"),
    ('[[criteria]]\nkind = "tests"\npoints = 1\npartial = "yes"\n', "`partial` must be true"),
    ('[[criteria]]\nkind = "build"\npoints = 1\nvisibility = "public"\n', "`visibility`"),
    ('[limits]\ntimeout = 0\n[[criteria]]\nkind = "build"\npoints = 1\n', "positive number"),
    ('[limits]\nswap = 1\n[[criteria]]\nkind = "build"\npoints = 1\n', "unknown key `swap`"),
    ('[[criteria]]\nkind = "build"\npoints = 1\n[[criteria]]\nkind = "build"\npoints = 1\n',
     "used twice"),
    ("criteria = [", "not valid TOML"),
    ('[[criteria]]\nkind = "style"\npoints = 1\nper_finding = -1\n', "more than 0"),
    ('[[criteria]]\nkind = "tests"\npoints = 1\nmin_tests = -2\n', "`min_tests` must be at"),
])
def test_mistakes_are_reported_with_their_place(tmp_path: Path, text: str, message: str) -> None:
    with pytest.raises(RubricError, match=message):
        _load(tmp_path, text)


def test_a_missing_rubric_is_a_clear_error(tmp_path: Path) -> None:
    with pytest.raises(RubricError, match="Cannot read the rubric"):
        load_rubric(tmp_path / "nope.toml")


def test_tomli_w_is_imported_only_to_write_the_example() -> None:
    script = ("import sys\nimport pkgtool.cli, pkgtool.commands.grade, pkgtool.grade.init_rubric\n"
              "import pkgtool.grade.report, pkgtool.grade.rubric\n"
              "before = 'tomli_w' in sys.modules\n"
              "pkgtool.grade.init_rubric.example_rubric()\n"
              "print(before, 'tomli_w' in sys.modules)\n")
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                          timeout=60, check=True)
    assert done.stdout.split() == ["False", "True"]
