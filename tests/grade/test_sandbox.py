"""The sandbox holds: time, processes, memory, output, files, network, environment.

Every dangerous command here runs with small limits that are checked to be in force first.
"""

from __future__ import annotations

import os
import sys
import uuid
from pathlib import Path

import pytest

from pkgtool.grade.jail import jail_support
from pkgtool.grade.sandbox import Limits, Sandbox, sandbox
from pkgtool.ros.colcon import ColconRun
from tests.helpers import no_process_with

PY = sys.executable


def _run(command: list[str], limits: Limits,
         mode: str | None = None) -> tuple[ColconRun, Sandbox]:
    with sandbox(limits, mode=mode) as box:
        run = box.run(command, box.workspace, box.base_env())
        return run, box


def _needs_jail(box: Sandbox) -> None:
    """Skip, saying why, when this machine gives no namespaces (the check needs a jail)."""
    if box.mode == "none":
        pytest.skip(f"no namespaces on this machine: {jail_support().reason}")


@pytest.fixture(scope="module")
def bounded() -> Sandbox:
    """A sandbox whose process limit is known to hold; dangerous tests skip without one."""
    with sandbox(Limits()) as box:
        if not box.bounds_processes:
            pytest.skip("no process limit can be enforced here (root without namespaces/cgroups)")
        return box


NAMESPACES = ("mnt", "net", "pid", "ipc", "uts", "cgroup")


def test_the_described_isolation_is_in_force() -> None:
    """Every namespace the description names is really new, the uid is the job's own, no new
    privileges can be gained, and no user namespace can be made inside."""
    if jail_support().mode != "root":
        pytest.skip(f"the root jail is not available here: {jail_support().reason}")
    probe = (f"readlink {' '.join(f'/proc/self/ns/{n}' for n in NAMESPACES)}; id -u; "
             "grep NoNewPrivs /proc/self/status; grep CapEff /proc/self/status; "
             "unshare --user true 2>/dev/null && echo userns-allowed || echo userns-denied")
    run, box = _run(["sh", "-c", probe], Limits(timeout=20))
    text = box.describe()
    lines = run.output.split()
    for name in NAMESPACES:
        host = os.readlink(f"/proc/self/ns/{name}")
        assert host not in lines and any(w.startswith(f"{name}:[") for w in lines), run.output
    assert str(box.uid) in lines and box.uid != 0, run.output
    assert "NoNewPrivs:\t1" in run.output and "CapEff:\t0000000000000000" in run.output
    assert "userns-denied" in lines, run.output
    assert "mount, net (loopback only), pid, ipc, uts, cgroup" in text
    assert f"unprivileged uid {box.uid}, no capabilities, no_new_privs" in text
    assert "new user namespaces forbidden" in text and "limits:" in text


def test_wall_clock_timeout_kills_the_whole_process_group() -> None:
    marker = f"1000.{uuid.uuid4().int % 10**6}"
    run, _ = _run(["sh", "-c", f"sleep {marker} & sleep {marker}"], Limits(timeout=1))
    assert run.timed_out and run.limit == "timed out after 1 s"
    assert no_process_with(marker)


def test_a_fork_bomb_is_bounded_and_cleaned_up(bounded: Sandbox) -> None:
    """Forks until the cap refuses one, then stops: the cap, not the clock, ends the step."""
    marker = f"bomb{uuid.uuid4().hex[:8]}"
    bomb = (f"import os, sys, time\n# {marker}\nmade = 0\nwhile made < 1000:\n    try:\n"
            "        if os.fork() == 0:\n            time.sleep(600)\n            os._exit(0)\n"
            "        made += 1\n    except OSError:\n        break\n"
            "print('forked', made, flush=True)\nsys.exit(3)\n")
    run, _ = _run([PY, "-c", bomb], Limits(timeout=60, processes=16))
    assert not run.timed_out, run.output
    assert "too many processes (limit 16)" in (run.limit or ""), (run.limit, run.output)
    forked = int(run.output.split("forked", 1)[1].split()[0])
    assert forked < 16, run.output
    assert no_process_with(marker)


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
    _needs_jail(box)
    assert "no network" in run.output


def test_the_machine_is_read_only_except_the_workspace(tmp_path: Path) -> None:
    victim = tmp_path / "victim.txt"
    victim.write_text("original")
    marker = Path("/tmp") / f"pkgtool-escape-{uuid.uuid4().hex}"
    script = f"echo x > {victim}; echo x > {marker}; echo mine > own.txt && cat own.txt"
    run, box = _run(["sh", "-c", script], Limits(timeout=20))
    assert "mine" in run.output
    _needs_jail(box)
    assert victim.read_text() == "original" and not marker.exists()


def test_the_environment_is_scrubbed(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("PKGTOOL_TEST_SECRET", "hunter2")
    run, box = _run(["sh", "-c", "env; id -u"], Limits(timeout=20))
    assert "hunter2" not in run.output
    assert f"HOME={box.workspace}/home" in run.output
    if box.uid is None:
        pytest.skip(f"no own uid in sandbox mode {box.mode} (not root)")
    assert str(box.uid) in run.output.split()


def test_the_user_namespace_mode_also_isolates() -> None:
    from pkgtool.grade.jail import mode_problem

    if mode_problem("userns"):
        pytest.skip(f"user namespaces are not available here: {mode_problem('userns')}")
    marker = f"pkgtool-userns-{uuid.uuid4().hex}"
    script = (f"touch /usr/{marker} 2>/dev/null || echo read-only; echo x > /tmp/{marker}; "
              "unshare --user true 2>/dev/null && echo userns-allowed || echo userns-denied")
    run, _ = _run(["sh", "-c", script], Limits(timeout=20), mode="userns")
    assert run.returncode == 0 and "read-only" in run.output, run.output
    assert "userns-denied" in run.output, run.output
    assert not Path(f"/usr/{marker}").exists() and not Path(f"/tmp/{marker}").exists()


def test_cpu_time_is_limited() -> None:
    run, _ = _run([PY, "-c", "while True:\n    pass"], Limits(timeout=60, cpu_seconds=1))
    assert run.limit == "killed: CPU time (limit 1 s)"
