"""Run untrusted commands in a job's temporary workspace, under limits, and say which one hit.

Every command gets: a new session (its process group is killed on timeout and at the end),
rlimits set before it starts (CPU, file size, core dumps; address space or process count
where no cgroup does it better), a per-job cgroup capping processes and memory when the
machine allows, a scrubbed environment, an output cap, and the strongest jail of
:mod:`pkgtool.grade.jail` (no network, read-only machine, unprivileged uid).
"""

from __future__ import annotations

import os
import resource
import secrets
import selectors
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path

from pkgtool.grade.cgroup import cgroups_available, create_job_cgroup
from pkgtool.grade.jail import JAIL_FAILED, SYSTEM_PATH, jail_command, jail_support
from pkgtool.ros.colcon import ColconRun

MB = 1024 * 1024


@dataclass(frozen=True, slots=True)
class Limits:
    """What one sandboxed command may use; ``timeout`` is wall-clock seconds."""

    timeout: float = 300.0
    memory_mb: int = 2048
    processes: int = 256
    cpu_seconds: int = 600
    file_size_mb: int = 256
    output_kb: int = 256


class Sandbox:
    """One job's sandbox: a private workspace folder, a uid and the limits for its commands."""

    def __init__(self, workspace: Path, limits: Limits, *, mode: str | None = None) -> None:
        self.workspace = workspace
        self.limits = limits
        self.mode = mode or jail_support().mode
        self.uid = 1_000_000 + secrets.randbelow(1_000_000) if self.mode == "root" else None
        self.cgroups = cgroups_available()

    @property
    def bounds_processes(self) -> bool:
        """True when a process-count limit really holds (root ignores RLIMIT_NPROC)."""
        return self.cgroups or self.uid is not None or os.geteuid() != 0

    def give(self, path: Path) -> None:
        """Hand ``path`` (and everything below it) to the sandbox's uid so commands can write."""
        if self.uid is None:
            return
        os.lchown(path, self.uid, self.uid)
        for folder, dirs, files in os.walk(path):
            for name in dirs + files:
                os.lchown(os.path.join(folder, name), self.uid, self.uid)

    def base_env(self) -> dict[str, str]:
        """The scrubbed environment every command starts from (ROS variables come on top)."""
        home, tmp = self.workspace / "home", self.workspace / "tmp"
        for folder in (home, tmp):
            folder.mkdir(exist_ok=True)
            self.give(folder)
        return {"PATH": f"{Path(sys.executable).parent}:{SYSTEM_PATH}", "LANG": "C.UTF-8",
                "HOME": str(home), "TMPDIR": str(tmp), "USER": "pkgtool-sandbox",
                "LOGNAME": "pkgtool-sandbox", "NO_COLOR": "1", "TERM": "dumb"}

    def describe(self) -> str:
        """Which isolation is in force, for reports."""
        parts = {"root": ["namespaces: net, pid, mount (read-only machine)",
                          f"unprivileged uid {self.uid}"],
                 "userns": ["namespaces: user, net, pid, mount (read-only machine)"],
                 "none": [f"no namespaces ({jail_support().reason or 'disabled'})"]}[self.mode]
        parts.append("cgroup: pids, memory" if self.cgroups else "no cgroup")
        if not self.bounds_processes:
            parts.append("process count NOT limited (root, without a cgroup or a uid change)")
        limits = self.limits
        parts.append(f"limits: {limits.timeout:g} s wall, {limits.memory_mb} MB, "
                     f"{limits.processes} processes, {limits.cpu_seconds} s CPU, "
                     f"{limits.file_size_mb} MB files, {limits.output_kb} KB output kept")
        return "; ".join(parts)

    def run(self, command: Sequence[str], cwd: Path, env: Mapping[str, str],
            timeout: float | None = None) -> ColconRun:
        """Run ``command`` in the sandbox; never raises for anything the command does."""
        limit = min(timeout or self.limits.timeout, self.limits.timeout)
        cgroup = None
        if self.cgroups:
            cgroup = create_job_cgroup(max_pids=self.limits.processes,
                                       memory_bytes=self.limits.memory_mb * MB)
        full = list(command) if self.mode == "none" else jail_command(
            command, workspace=self.workspace, uid=self.uid, mode=self.mode)
        start = time.monotonic()
        procs = [os.open(path, os.O_WRONLY) for path in cgroup.procs_files()] if cgroup else []
        try:
            process = subprocess.Popen(full, cwd=cwd, env=dict(env), stdin=subprocess.DEVNULL,
                                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                       start_new_session=True,
                                       preexec_fn=self._preexec(procs, cgroup is not None))
        except OSError as error:
            if cgroup:
                cgroup.remove()
            return ColconRun(tuple(command), 127, f"cannot start `{command[0]}`: {error}", 0.0)
        finally:
            for fd in procs:
                os.close(fd)
        output, stopped = _collect(process, limit, self.limits.output_kb * 1024)
        seconds = time.monotonic() - start
        events = cgroup.events() if cgroup else {}
        if cgroup:
            cgroup.remove()
        if process.returncode == JAIL_FAILED and "pkgtool-jail:" in output:
            raise RuntimeError(f"The sandbox could not be set up: {output.strip()}")
        hits = _limits_hit(self.limits, limit, stopped, events, process.returncode, output,
                           cgroup is not None)
        return ColconRun(tuple(command), process.returncode, output, seconds,
                         timed_out=stopped == "timeout", limit="; ".join(hits) or None)

    def _preexec(self, procs: list[int], in_cgroup: bool) -> Callable[[], None]:
        """The function run in the child before exec: join the cgroup, set the rlimits."""
        limits = self.limits
        rlimits = [(resource.RLIMIT_CPU, limits.cpu_seconds, limits.cpu_seconds + 5),
                   (resource.RLIMIT_FSIZE, limits.file_size_mb * MB, limits.file_size_mb * MB),
                   (resource.RLIMIT_CORE, 0, 0)]
        if not in_cgroup:
            rlimits.append((resource.RLIMIT_AS, limits.memory_mb * MB, limits.memory_mb * MB))
        if self.uid is not None or not in_cgroup:
            allowed = limits.processes + (0 if self.uid is not None else _own_process_count())
            rlimits.append((resource.RLIMIT_NPROC, allowed, allowed))

        def preexec() -> None:
            for fd in procs:
                os.write(fd, b"0")
            for which, soft, hard in rlimits:
                resource.setrlimit(which, (soft, hard))

        return preexec


@contextmanager
def sandbox(limits: Limits, *, mode: str | None = None) -> Iterator[Sandbox]:
    """A sandbox with a fresh workspace folder, removed with everything in it afterwards."""
    job = Path(tempfile.mkdtemp(prefix="pkgtool-job-"))
    try:
        os.chmod(job, 0o711)
        workspace = job / "ws"
        workspace.mkdir()
        box = Sandbox(workspace, limits, mode=mode)
        box.give(workspace)
        yield box
    finally:
        shutil.rmtree(job, ignore_errors=True)


def _own_process_count() -> int:
    uid = os.getuid()
    return sum(1 for p in Path("/proc").iterdir() if p.name.isdigit() and _owner(p) == uid)


def _owner(path: Path) -> int | None:
    try:
        return path.stat().st_uid
    except OSError:
        return None


def _collect(process: subprocess.Popen[bytes], timeout: float, keep: int) -> tuple[str, str]:
    """Read output until exit or ``timeout``, keeping head and tail; kill the group if stopped.

    Returns the text and why it was stopped early: ``timeout``, ``output`` or ``""``.
    """
    assert process.stdout is not None
    head, tail, total, stopped = bytearray(), bytearray(), 0, ""
    deadline = time.monotonic() + timeout
    grace: float | None = None
    with selectors.DefaultSelector() as selector:
        selector.register(process.stdout, selectors.EVENT_READ)
        while True:
            now = time.monotonic()
            if now >= deadline:
                stopped = "timeout"
                break
            if grace is None and process.poll() is not None:
                grace = now + 1.0  # background children may hold the pipe: not for long
            if grace is not None and now >= grace:
                break
            if not selector.select(timeout=min(0.2, deadline - now)):
                continue
            chunk = os.read(process.stdout.fileno(), 65536)
            if not chunk:
                break
            total += len(chunk)
            room = keep - len(head)
            if room > 0:
                head += chunk[:room]
                chunk = chunk[room:]
            tail = (tail + chunk)[-keep:]
            if total > 64 * keep:
                stopped = "output"
                break
    _kill_group(process)
    process.stdout.close()
    omitted = total - len(head) - len(tail)
    middle = f"\n[... {omitted} bytes of output omitted ...]\n".encode() if omitted > 0 else b""
    return (bytes(head) + middle + bytes(tail)).decode(errors="replace"), stopped


def _kill_group(process: subprocess.Popen[bytes]) -> None:
    try:
        os.killpg(process.pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass
    process.wait()


def _limits_hit(limits: Limits, timeout: float, stopped: str, events: dict[str, int],
                returncode: int, output: str, in_cgroup: bool) -> list[str]:
    """Plain words for every limit the run hit (from the cgroup's counters, else its output)."""
    hits = []
    if stopped == "timeout":
        hits.append(f"timed out after {timeout:g} s")
    if stopped == "output":
        hits.append(f"killed: output over {64 * limits.output_kb} KB")
    if events.get("memory") or (not in_cgroup and "MemoryError" in output):
        hits.append(f"killed: memory (limit {limits.memory_mb} MB)")
    if events.get("pids") or (not in_cgroup and "Resource temporarily unavailable" in output):
        hits.append(f"killed: too many processes (limit {limits.processes})")
    if returncode in (-signal.SIGXCPU, 128 + signal.SIGXCPU):
        hits.append(f"killed: CPU time (limit {limits.cpu_seconds} s)")
    if "File too large" in output:
        hits.append(f"file size limit reached ({limits.file_size_mb} MB)")
    return hits
