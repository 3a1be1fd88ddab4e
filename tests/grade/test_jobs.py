"""Jobs on untrusted input: each under a deadline and a memory cap, results as each one ends."""

from __future__ import annotations

import time
from pathlib import Path

import pytest

from pkgtool.grade.jobs import Task, run_tasks


def _sleep(seconds: float) -> str:
    time.sleep(seconds)
    return f"slept {seconds:g}"


def _hog(megabytes: int) -> str:
    block = bytearray(megabytes * 1024 * 1024)
    return f"allocated {len(block)}"


def _failed(reason: str) -> str:
    return f"failed: {reason}"


def test_a_job_past_its_deadline_is_killed_and_the_others_go_on() -> None:
    done: list[str] = []
    results = run_tasks([Task(_sleep, (600,), 10.0, _failed), Task(_sleep, (0,), 600.0, _failed)],
                        jobs=2, on_done=done.append)
    assert results == ["failed: the job ran out of time (deadline 10 s)", "slept 0"]
    assert done == ["slept 0", results[0]], "a result waited for a slower job"


def test_a_job_is_capped_in_memory() -> None:
    hog, small = run_tasks([Task(_hog, (2048,), 600.0, _failed, memory_mb=256),
                            Task(_hog, (16,), 600.0, _failed, memory_mb=256)], jobs=1)
    assert hog == "failed: internal error: MemoryError: " and small == f"allocated {16 << 20}"


def test_an_archive_is_unpacked_as_the_jobs_uid(tmp_path: Path) -> None:
    from pkgtool.grade.sandbox import Limits, sandbox
    from pkgtool.grade.stage import stage
    from tests.grade.synthetic import bytes_zip

    archive = tmp_path / "alice.zip"
    archive.write_bytes(bytes_zip({"pkg/package.xml": b"<package/>", "pkg/a.py": b"x"}))
    with sandbox(Limits(timeout=60)) as box:
        if box.uid is None:
            pytest.skip(f"no own uid for jobs in sandbox mode {box.mode} (not root)")
        tree = stage(archive, box)
        owners = {path.stat().st_uid for path in [tree, *tree.rglob("*")]}
        assert owners == {box.uid}
        assert (tree / "pkg" / "a.py").read_bytes() == b"x"
