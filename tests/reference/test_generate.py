"""`pkgtool reference generate`: exact copies, support packages, and never an overwrite."""

from __future__ import annotations

from pathlib import Path

import pytest
from typer.testing import CliRunner

from pkgtool.cli import _register, app
from pkgtool.commands import ExitCode
from pkgtool.commands.reference import (
    SUPPORT_FOLDER, _job_seconds, catalog, generate, run_tests)
from pkgtool.resources import resource_dir

_register()
ROOT = resource_dir("reference_packages")


def _tree(folder: Path) -> dict[str, bytes]:
    caches = {"__pycache__", ".pytest_cache"}
    return {p.relative_to(folder).as_posix(): p.read_bytes()
            for p in sorted(folder.rglob("*")) if p.is_file() and not caches & set(p.parts)}


def _generate(*args: str):
    return CliRunner().invoke(app, ["reference", "generate", *args])


def test_generate_copies_the_package_byte_for_byte(tmp_path: Path) -> None:
    result = _generate("physical_ai_sensors", "physical_ai_camera", "--dest", str(tmp_path))
    assert result.exit_code == 0, result.output
    assert "generated" in result.output
    for name in ("physical_ai_sensors", "physical_ai_camera"):
        assert _tree(tmp_path / name) == _tree(ROOT / name)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["physical_ai_camera",
                                                          "physical_ai_sensors"]


def test_ctrl_c_takes_back_the_packages_already_generated(tmp_path: Path,
                                                          monkeypatch) -> None:
    from pkgtool.create import writer

    calls = []
    real = writer.write_package

    def interrupted_second(target, files):  # type: ignore[no-untyped-def]
        calls.append(target)
        if len(calls) == 2:
            raise KeyboardInterrupt
        return real(target, files)

    monkeypatch.setattr(writer, "write_package", interrupted_second)
    with pytest.raises(KeyboardInterrupt):
        generate(["robot_monitor", "nav_agent"], dest=tmp_path)
    assert len(calls) == 2 and list(tmp_path.iterdir()) == []


def test_generate_all_adds_support_packages_once(tmp_path: Path) -> None:
    result = generate([], all_=True, dest=tmp_path)
    assert result.exit_code is ExitCode.OK, result.errors
    support = {s for entry in catalog() for s in entry.support}
    expected = {entry.name for entry in catalog()} | support
    assert {p.name for p in result.written} == expected == {p.name for p in tmp_path.iterdir()}
    for name in support:
        assert _tree(tmp_path / name) == _tree(ROOT / SUPPORT_FOLDER / name)


def test_generate_refuses_to_overwrite_and_writes_nothing(tmp_path: Path) -> None:
    (tmp_path / "physical_ai_camera").mkdir()
    (tmp_path / "physical_ai_camera" / "mine.txt").write_text("my work")
    result = _generate("physical_ai_sensors", "physical_ai_camera", "--dest", str(tmp_path))
    assert result.exit_code == 2
    assert "already exists" in result.output and "never overwrites" in result.output
    assert sorted(p.name for p in tmp_path.iterdir()) == ["physical_ai_camera"]
    assert [p.name for p in (tmp_path / "physical_ai_camera").iterdir()] == ["mine.txt"]


def test_existing_support_package_is_kept(tmp_path: Path) -> None:
    needing = next(e for e in catalog() if e.support)  # nav_agent needs nav2_msgs
    own = tmp_path / needing.support[0]
    own.mkdir()
    result = generate([needing.name], dest=tmp_path)
    assert result.exit_code is ExitCode.OK
    assert result.kept == (own,) and not any(own.iterdir())


def test_unknown_or_missing_names_are_usage_errors(tmp_path: Path) -> None:
    unknown = _generate("physical_ai_robot", "--dest", str(tmp_path))
    assert unknown.exit_code == 2
    assert "Unknown reference package `physical_ai_robot`" in unknown.output
    assert _generate("--dest", str(tmp_path)).exit_code == 2
    assert not any(tmp_path.iterdir())


def test_test_command_checks_its_arguments_before_doing_anything(tmp_path: Path) -> None:
    (tmp_path / "stuff").write_text("x")
    result = run_tests(["physical_ai_camera"], keep=tmp_path)
    assert result.exit_code is ExitCode.USAGE and "not empty" in result.errors[0]
    assert run_tests(["nope"]).exit_code is ExitCode.USAGE
    cli = CliRunner().invoke(app, ["reference", "test"])
    assert cli.exit_code == 2 and "--all" in cli.output


def test_job_seconds_are_read_from_colcon_events(tmp_path: Path) -> None:
    log = tmp_path / "events.log"
    log.write_text(
        "[0.000000] (-) TimerEvent: {}\n"
        "[0.500000] (pkg_a) JobStarted: {'identifier': 'pkg_a'}\n"
        "[0.600000] (pkg_b) JobStarted: {'identifier': 'pkg_b'}\n"
        "[3.000000] (pkg_a) JobEnded: {'identifier': 'pkg_a', 'rc': 0}\n"
        "[9.100000] (pkg_b) JobEnded: {'identifier': 'pkg_b', 'rc': 1}\n")
    assert _job_seconds(log) == {"pkg_a": 2.5, "pkg_b": 8.5}
    assert _job_seconds(tmp_path / "missing.log") == {}
