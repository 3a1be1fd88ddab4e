"""`pkgtool reference test --all`: every reference package lint-clean, built and tested for real.

One colcon workspace holds all of them (and their support packages): the same run as the
README's main job, with real rclpy in each package's own tests.
"""

from __future__ import annotations

import tempfile
from pathlib import Path

import pytest

from pkgtool.commands import ExitCode
from pkgtool.commands.reference import catalog, run_tests

pytestmark = [pytest.mark.ros, pytest.mark.colcon, pytest.mark.slow]


def test_every_reference_package_lints_clean_builds_and_passes_its_tests(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    system_temp = tmp_path / "system-temp"  # this run's own system temp folder, empty
    system_temp.mkdir()
    monkeypatch.setenv("TMPDIR", str(system_temp))
    monkeypatch.setattr(tempfile, "tempdir", None)  # re-read TMPDIR
    stages: list[tuple[str, str]] = []
    result = run_tests([], all_=True, jobs=2, progress=lambda *event: stages.append(event))
    problems = [f"{r.name}: findings={list(r.findings)} built={r.built} "
                f"tests={r.summary.describe() if r.summary else None}\n{r.output}"
                for r in result.packages if not r.ok]
    assert result.exit_code is ExitCode.OK, "\n".join(problems) or result.errors
    assert [r.name for r in result.packages] == [e.name for e in catalog()]
    for report in result.packages:
        assert report.summary is not None and report.summary.ran >= 5, report.name
        assert (report.name, "passed") in stages
        assert report.seconds > 0
    assert result.workspace is None  # the temporary workspace was removed
    assert sorted(p.name for p in system_temp.iterdir()) == []  # and nothing else was left
