"""``pkgtool grade --init-rubric``: a complete, commented example rubric.

tomli-w writes TOML but no comments, so each table is serialised by tomli-w on its own and
the comments are attached afterwards: a block above each table, and a trailing comment on
the lines whose key has one. The result is checked by loading it back in the tests.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

HEADER = """\
# pkgtool grading rubric. Grade with:
#   pkgtool grade SUBMISSION... --rubric this-file.toml [--format text|json|junit|gradescope|csv]
# Every criterion gives `points`; most give partial credit. Students see `feedback` when a
# criterion is not met in full. docs/grading.md describes every key.
"""

_TOP: dict[str, Any] = {"title": "robot_monitor assignment", "package": "robot_monitor"}
_TOP_NOTES = {"title": "shown in reports",
              "package": "the graded package when a submission holds several"}
_LIMITS: dict[str, Any] = {"timeout": 300, "test_timeout": 60, "memory_mb": 2048,
                           "processes": 256, "cpu_seconds": 600, "file_size_mb": 256,
                           "output_kb": 256, "disk_mb": 1024}
_LIMIT_NOTES = {"timeout": "wall-clock seconds per build or test step",
                "test_timeout": "seconds per single test, and per console script load",
                "memory_mb": "memory of a whole step", "processes": "processes and threads",
                "cpu_seconds": "CPU time per process", "file_size_mb": "largest file written",
                "output_kb": "log kept per step (head and tail)",
                "disk_mb": "the job's own filesystem (as root; else per file only)"}
_NOTES = {"visibility": "Gradescope: visible, hidden, after_due_date, after_published",
          "per_finding": "points lost per finding; leave out for all-or-nothing",
          "partial": "proportional credit (false: all or nothing)",
          "min_tests": "fewer tests than this scores zero",
          "path": "relative to this file; run against the installed package",
          "select": "rule codes, families or names", "names": "console_scripts entries"}
_CRITERIA: list[tuple[str, dict[str, Any]]] = [
    ("The package builds with `colcon build`; without it no test below can run.",
     {"kind": "build", "name": "Builds with colcon", "points": 2,
      "feedback": "Run `colcon build --packages-select robot_monitor` and fix the first error"}),
    ("Each console script is declared, installed in lib/<package> and importable.",
     {"kind": "executables", "points": 2, "partial": True,
      "names": ["battery_monitor", "temperature_monitor"]}),
    ("Lint rules that must report nothing (selected like `pkgtool lint --select`).",
     {"kind": "lint", "name": "Dependencies and entry points declared", "points": 2,
      "select": ["ENT", "DEP"], "min_severity": "warning", "per_finding": 0.5}),
    ("ament's flake8 and pep257 settings, through pkgtool's STY rules.",
     {"kind": "style", "points": 1, "per_finding": 0.25}),
    ("The student's own tests (`colcon test`) pass; credit in proportion to passing tests.",
     {"kind": "tests", "points": 1, "min_tests": 1, "exclude": ["test/test_copyright.py"]}),
    ("Instructor tests, run by the grader's own pytest against the installed package.",
     {"kind": "hidden", "name": "Instructor tests", "points": 6, "path": "hidden_tests",
      "visibility": "after_published",
      "feedback": "Compare your nodes with the assignment's topic names and message types"}),
]
EXAMPLE_TEST = '''\
"""An instructor test: runs against the student's installed package."""


def test_package_imports():
    import robot_monitor  # noqa: F401
'''


def example_rubric() -> str:
    """The commented example rubric as TOML text."""
    import tomli_w

    parts = [HEADER, _annotate(tomli_w.dumps(_TOP), _TOP_NOTES),
             "# Sandbox limits for every step of every submission.",
             "[limits]\n" + _annotate(tomli_w.dumps(_LIMITS), _LIMIT_NOTES)]
    for comment, criterion in _CRITERIA:  # each table's keys by tomli-w, under its header
        parts += [f"# {comment}", "[[criteria]]\n" + _annotate(tomli_w.dumps(criterion), _NOTES)]
    return "\n".join(parts)


def write_example(path: Path) -> list[Path]:
    """Write the example rubric, and its hidden-test folder if absent; return what was written."""
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(example_rubric(), encoding="utf-8")
    written = [path]
    tests = path.parent / "hidden_tests"
    if not tests.exists():
        tests.mkdir(parents=True)
        (tests / "test_hidden_example.py").write_text(EXAMPLE_TEST, encoding="utf-8")
        written.append(tests / "test_hidden_example.py")
    return written


def _annotate(text: str, notes: dict[str, str]) -> str:
    lines = []
    for line in text.splitlines():
        match = re.match(r"^(\w+) = ", line)
        note = notes.get(match.group(1)) if match else None
        if note and len(line) + len(note) < 96:
            lines.append(f"{line}  # {note}")
        else:
            lines += [f"# {note}", line] if note else [line]
    return "\n".join(lines) + "\n"
