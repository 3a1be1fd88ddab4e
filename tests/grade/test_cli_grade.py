"""`pkgtool grade` command line: --init-rubric, usage errors, the formats of one submission."""

from __future__ import annotations

import csv
import io
import json
from pathlib import Path

from tests.grade import synthetic
from tests.helpers import run_cli


def _rubric(tmp_path: Path) -> Path:
    path = tmp_path / "rubric.toml"
    path.write_text(synthetic.RUBRIC.format(timeout=30, hidden=synthetic.HIDDEN))
    return path


def test_init_rubric_writes_a_usable_example_once(tmp_path: Path) -> None:
    first = run_cli("grade", "--init-rubric", "course/rubric.toml", cwd=tmp_path)
    assert first.exit_code == 0, first.output
    assert (tmp_path / "course" / "hidden_tests" / "test_hidden_example.py").is_file()
    again = run_cli("grade", "--init-rubric", "course/rubric.toml", cwd=tmp_path)
    assert again.exit_code == 2 and "already exists" in again.output


def test_usage_errors_exit_2(tmp_path: Path) -> None:
    _rubric(tmp_path)
    (tmp_path / "bad.toml").write_text('[[criteria]]\nkind = "lint"\npoints = 1\n')
    cases = [
        (["grade", "x"], "--rubric FILE"),
        (["grade", "nope", "--rubric", "rubric.toml"], "`nope` does not exist"),
        (["grade", "--rubric", "rubric.toml"], "at least one submission"),
        (["grade", ".", "--rubric", "bad.toml"], "list rule codes"),
        (["grade", "rubric.toml", "--batch", "--rubric", "rubric.toml"], "must be a folder"),
        (["grade", ".", ".", "--rubric", "rubric.toml", "--format", "gradescope"],
         "exactly one submission"),
    ]
    for args, message in cases:
        result = run_cli(*args, cwd=tmp_path)
        assert result.exit_code == 2 and message in result.output, (args, result.output)


def test_gradescope_and_csv_for_an_unsafe_archive(tmp_path: Path) -> None:
    _rubric(tmp_path)
    synthetic.write_submission(tmp_path / "pkg", synthetic.correct())
    synthetic.zip_with_traversal(tmp_path / "eve.zip", tmp_path / "pkg")
    result = run_cli("grade", "eve.zip", "--rubric", "rubric.toml", "--format", "gradescope",
                     "-o", "results.json", cwd=tmp_path)
    assert result.exit_code == 0, result.output
    document = json.loads((tmp_path / "results.json").read_text())
    assert document["score"] == 0 and "points outside the submission" in document["output"]
    assert len(document["tests"]) == 6
    assert all(t["status"] == "failed" and t["max_score"] > 0 for t in document["tests"])
    result = run_cli("grade", "eve.zip", "--rubric", "rubric.toml", "--format", "csv",
                     cwd=tmp_path)
    rows = list(csv.reader(io.StringIO(result.stdout)))
    assert rows[1][:4] == ["eve", "", "0.0", "11.0"]
