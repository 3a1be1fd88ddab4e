"""The sandbox holds: time, processes, memory, output, files, network, environment.

Every dangerous command here runs with small limits that are checked to be in force first.
"""

from __future__ import annotations

import os
import sys
import time
import uuid
from pathlib import Path

import pytest

from pkgtool.grade.jail import jail_support
from pkgtool.grade.sandbox import Limits, Sandbox, sandbox
from pkgtool.ros.colcon import ColconRun

PY = sys.executable


def _run(command: list[str], limits: Limits,
         mode: str | None = None) -> tuple[ColconRun, Sandbox]:
    with sandbox(limits, mode=mode) as box:
        run = box.run(command, box.workspace, box.base_env())
        return run, box


def _leftovers(marker: str) -> list[int]:
    """Host pids whose command line holds ``marker``."""
    found = []
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit() and entry.name != str(os.getpid()):
            try:
                if marker.encode() in (entry / "cmdline").read_bytes():
                    found.append(int(entry.name))
            except OSError:
                pass
    return found


@pytest.fixture(scope="module")
def bounded() -> Sandbox:
    """A sandbox whose process limit is known to hold; dangerous tests skip without one."""
    with sandbox(Limits()) as box:
        if not box.bounds_processes:
            pytest.skip("no process limit can be enforced here (root without namespaces/cgroups)")
        return box


def test_this_machine_gives_the_strongest_isolation() -> None:
    with sandbox(Limits()) as box:
        text = box.describe()
    if os.geteuid() == 0 and jail_support().mode == "root":
        assert "namespaces: net, pid, mount" in text and "unprivileged uid" in text
    assert "limits:" in text


def test_wall_clock_timeout_kills_the_whole_process_group() -> None:
    marker = f"1000.{uuid.uuid4().int % 10**6}"
    start = time.monotonic()
    run, _ = _run(["sh", "-c", f"sleep {marker} & sleep {marker}"], Limits(timeout=1))
    assert time.monotonic() - start < 10
    assert run.timed_out and run.limit == "timed out after 1 s"
    time.sleep(0.2)
    assert not _leftovers(marker)


def test_a_fork_bomb_is_bounded_and_cleaned_up(bounded: Sandbox) -> None:
    marker = f"bomb{uuid.uuid4().hex[:8]}"
    bomb = (f"import os\n# {marker}\nwhile True:\n    try:\n        os.fork()\n"
            "    except OSError:\n        pass\n")
    run, _ = _run([PY, "-c", bomb], Limits(timeout=3, processes=16))
    assert "too many processes (limit 16)" in (run.limit or "") or run.timed_out
    time.sleep(0.2)
    assert not _leftovers(marker)


def test_memory_is_limited() -> None:
    hog = "x = bytearray(600 * 1024 * 1024)\nx[::4096] = b'1' * len(x[::4096])\nprint('survived')"
    run, _ = _run([PY, "-c", hog], Limits(timeout=20, memory_mb=200))
    assert "survived" not in run.output
    assert "killed: memory (limit 200 MB)" in (run.limit or "")


def test_output_is_capped_and_a_flood_is_stopped() -> None:
    flood = "import sys\nwhile True:\n    sys.stdout.write('x' * 4096)"
    run, _ = _run([PY, "-c", flood], Limits(timeout=20, output_kb=4))
    assert "killed: output over 256 KB" in (run.limit or "")
    assert len(run.output) < 3 * 4096 and "bytes of output omitted" in run.output


def test_file_size_is_limited() -> None:
    writer = "open('big', 'wb').write(b'0' * (3 * 1024 * 1024))"
    run, _ = _run([PY, "-c", writer], Limits(timeout=20, file_size_mb=1))
    assert run.returncode != 0 and "file size limit reached (1 MB)" in (run.limit or "")


def test_no_network_but_loopback_works() -> None:
    probe = ("import socket\n"
             "server = socket.socket(); server.bind(('127.0.0.1', 0)); server.listen()\n"
             "socket.create_connection(server.getsockname(), timeout=2); print('loopback ok')\n"
             "try:\n    socket.create_connection(('1.1.1.1', 80), timeout=2)\n"
             "except OSError as error:\n    print('no network:', error)\n")
    run, box = _run([PY, "-c", probe], Limits(timeout=20))
    assert "loopback ok" in run.output
    if box.mode != "none":
        assert "no network" in run.output


def test_the_machine_is_read_only_except_the_workspace(tmp_path: Path) -> None:
    victim = tmp_path / "victim.txt"
    victim.write_text("original")
    marker = Path("/tmp") / f"pkgtool-escape-{uuid.uuid4().hex}"
    script = f"echo x > {victim}; echo x > {marker}; echo mine > own.txt && cat own.txt"
    run, box = _run(["sh", "-c", script], Limits(timeout=20))
    assert "mine" in run.output
    if box.mode != "none":
        assert victim.read_text() == "original" and not marker.exists()


def test_the_environment_is_scrubbed(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("PKGTOOL_TEST_SECRET", "hunter2")
    run, box = _run(["sh", "-c", "env; id -u"], Limits(timeout=20))
    assert "hunter2" not in run.output
    assert f"HOME={box.workspace}/home" in run.output
    if box.uid is not None:
        assert str(box.uid) in run.output.split()


@pytest.mark.skipif(jail_support().mode == "none", reason="no namespaces on this machine")
def test_the_user_namespace_mode_also_isolates() -> None:
    run, _ = _run(["sh", "-c", "id -u; touch /tmp/pkgtool-userns-probe || echo read-only"],
                  Limits(timeout=20), mode="userns")
    assert run.returncode == 0 and "read-only" in run.output


def test_cpu_time_is_limited() -> None:
    run, _ = _run([PY, "-c", "while True:\n    pass"], Limits(timeout=60, cpu_seconds=1))
    assert run.limit == "killed: CPU time (limit 1 s)"
