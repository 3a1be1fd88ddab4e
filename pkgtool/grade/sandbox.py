"""Run untrusted commands in a job's temporary workspace, under limits, and say which one hit.

A job is a folder ``pkgtool-job-*``: its workspace ``ws`` (the only place commands may write),
``hidden`` (instructor tests, bound into the step that runs them only) and ``root`` (where
each jail builds its root). As root that folder is a tmpfs of ``disk_mb`` in this process's
private mount namespace (``hidden`` one of its own, which the student cannot fill): the
machine never sees the job's files and they vanish with it.

Every command gets: a new session (its process group is killed on timeout and at the end),
rlimits set before it starts (CPU, file size, core dumps; address space or process count
where no cgroup does it better), a per-step cgroup capping processes and memory when the
machine allows, death with the grading process (``PR_SET_PDEATHSIG``), a scrubbed
environment, an output cap, and the strongest jail of :mod:`pkgtool.grade.jail`.
"""

from __future__ import annotations

import functools
import os
import resource
import secrets
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from pathlib import Path

from pkgtool.grade import seccomp
from pkgtool.grade.cgroup import JobCgroup, cgroups_available, create_job_cgroup, sweep
from pkgtool.grade.collect import collect, kill_group
from pkgtool.safe_fs import remove_tree
from pkgtool.grade.jail import JAIL_FAILED, SYSTEM_PATH, jail_command, jail_support
from pkgtool.grade.limits import Limits, limits_hit
from pkgtool.grade.mounts import mount_tmpfs, unmount
from pkgtool.ros.colcon import ColconRun

__all__ = ["Limits", "Sandbox", "sandbox"]

MB = 1024 * 1024
HIDDEN_MB = 256
"""Size of the job's separate filesystem for the instructor's tests."""
JOB_PREFIX = "pkgtool-job-"
"""Job folders are ``<tmp>/pkgtool-job-<pid of the grading process>-<random>``."""
RESULTS_FD = "PKGTOOL_RESULTS_FD"
"""Environment variable naming a command's private results descriptor (see ``channel``)."""


class Sandbox:
    """One job's sandbox: its folder, a uid and the limits for its commands."""

    def __init__(self, job: Path, limits: Limits, *, mode: str | None = None) -> None:
        self.job = job
        self.workspace = job / "ws"
        self.hidden = job / "hidden"
        self.limits = limits
        self.mode = mode or jail_support().mode
        self.why = "" if mode else jail_support().reason
        own_uid = self.mode == "root" or (self.mode == "none" and os.geteuid() == 0)
        self.uid = 1_000_000 + secrets.randbelow(1_000_000) if own_uid else None
        self.cgroups = cgroups_available()
        self.disk = False
        """True when the job's folder is a tmpfs of ``disk_mb`` (the total disk use is capped)."""

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
        """Which isolation is in force, for reports: every item is what the code enforces."""
        forbidden = ("new user namespaces forbidden (seccomp)" if seccomp.available()
                     else "new user namespaces NOT forbidden")
        shared = ("mount, net (loopback only), pid, ipc, uts, cgroup; own root: system "
                  "folders read-only, private /tmp and /dev/shm, nothing else of the machine")
        parts = {"root": [f"namespaces: {shared}",
                          f"unprivileged uid {self.uid}, no capabilities, no_new_privs",
                          forbidden],
                 "userns": [f"namespaces: user, {shared}", "no capabilities, no_new_privs",
                            "new user namespaces forbidden (user.max_user_namespaces = 0)"],
                 "none": [f"no namespaces ({self.why or 'sandbox mode none chosen'})",
                          *([f"unprivileged uid {self.uid}, no_new_privs", forbidden]
                            if self.uid is not None else [])]}[self.mode]
        parts.append(f"disk: {self.limits.disk_mb} MB (own tmpfs)" if self.disk
                     else "disk: per file only")
        parts.append("cgroup: pids, memory" if self.cgroups else "no cgroup")
        if not self.bounds_processes:
            parts.append("process count NOT limited (root, without a cgroup or a uid change)")
        limits = self.limits
        parts.append(f"limits: {limits.timeout:g} s wall, {limits.memory_mb} MB, "
                     f"{limits.processes} processes, {limits.cpu_seconds} s CPU, "
                     f"{limits.file_size_mb} MB files, {limits.output_kb} KB output kept")
        return "; ".join(parts)

    def run(self, command: Sequence[str], cwd: Path, env: Mapping[str, str],
            timeout: float | None = None, *, channel: bool = False,
            extra: Sequence[Path] = ()) -> ColconRun:
        """Run ``command`` in the sandbox; never raises for anything the command does.

        With ``channel`` the command gets a private pipe, its number in ``PKGTOOL_RESULTS_FD``;
        what it writes there is ``ColconRun.channel``, read once every process of the run is
        dead. ``extra`` folders are visible, read-only, to this command only.
        """
        limit = min(timeout or self.limits.timeout, self.limits.timeout)
        cgroup = create_job_cgroup(max_pids=self.limits.processes,
                                   memory_bytes=self.limits.memory_mb * MB) \
            if self.cgroups else None
        env = dict(env)
        pipe = os.pipe() if channel else None
        if pipe:
            env[RESULTS_FD] = str(pipe[1])
        full = list(command) if self.mode == "none" else jail_command(
            command, root=self.job / "root", workspace=self.workspace, uid=self.uid,
            mode=self.mode, tmp_mb=self.limits.disk_mb, extra=extra)
        process, start = None, time.monotonic()
        try:
            process = self._start(full, cwd, env, cgroup, pipe[1] if pipe else None)
            if pipe:
                os.close(pipe[1])
            if process is None:
                return ColconRun(tuple(command), 127, f"cannot start `{command[0]}`", 0.0)
            got = collect(process, limit, self.limits.output_kb * 1024,
                          pipe[0] if pipe else None)
            events = cgroup.events() if cgroup else {}
        finally:
            if process is not None:
                kill_group(process)
            if cgroup:
                cgroup.remove()
            if pipe:
                os.close(pipe[0])
        if process.returncode == JAIL_FAILED and "pkgtool-jail:" in got.output:
            raise RuntimeError(f"The sandbox could not be set up: {got.output.strip()}")
        hits = limits_hit(self.limits, limit, got.stopped, events, process.returncode,
                          got.output, cgroup is not None)
        return ColconRun(tuple(command), process.returncode, got.output,
                         time.monotonic() - start, timed_out=got.stopped == "timeout",
                         limit="; ".join(hits) or None, channel=got.channel)

    def _start(self, full: list[str], cwd: Path, env: dict[str, str],
               cgroup: JobCgroup | None, results: int | None) -> subprocess.Popen[bytes] | None:
        procs = [os.open(path, os.O_WRONLY) for path in cgroup.procs_files()] if cgroup else []
        try:
            return subprocess.Popen(full, cwd=cwd, env=env, stdin=subprocess.DEVNULL,
                                    stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                    start_new_session=True,
                                    pass_fds=(results,) if results is not None else (),
                                    preexec_fn=self._preexec(procs, cgroup is not None))
        except OSError:
            return None
        finally:
            for fd in procs:
                os.close(fd)

    def _preexec(self, procs: list[int], in_cgroup: bool) -> Callable[[], None]:
        """The function run in the child before exec: join the cgroup, set the rlimits."""
        limits = self.limits
        rlimits = [(resource.RLIMIT_CPU, limits.cpu_seconds, limits.cpu_seconds + 5),
                   (resource.RLIMIT_FSIZE, limits.file_size_mb * MB, limits.file_size_mb * MB),
                   (resource.RLIMIT_CORE, 0, 0)]
        if not in_cgroup:
            rlimits.append((resource.RLIMIT_AS, limits.memory_mb * MB, limits.memory_mb * MB))
        else:  # the cgroup bounds memory; lift the grading process's own (soft) cap
            hard = resource.getrlimit(resource.RLIMIT_AS)[1]
            rlimits.append((resource.RLIMIT_AS, hard, hard))
        if self.uid is not None or not in_cgroup:
            allowed = limits.processes + (0 if self.uid is not None else _own_process_count())
            rlimits.append((resource.RLIMIT_NPROC, allowed, allowed))
        jailed, uid = self.mode != "none", self.uid

        def preexec() -> None:
            for fd in procs:
                os.write(fd, b"0")
            for which, soft, hard in rlimits:
                resource.setrlimit(which, (soft, hard))
            if not jailed:
                seccomp.no_new_privs()
            if uid is not None:
                seccomp.forbid_user_namespaces()
            if uid is not None and not jailed:  # in a jail, setpriv changes the uid
                os.setgroups([])
                os.setresgid(uid, uid, uid)
                os.setresuid(uid, uid, uid)
            seccomp.die_with_parent()  # last: a change of uid clears it

        return preexec


@functools.cache
def _swept() -> int:
    """Remove the cgroups of grading processes that died (once per process)."""
    return sweep()


@contextmanager
def sandbox(limits: Limits, *, mode: str | None = None) -> Iterator[Sandbox]:
    """A sandbox with a fresh job folder, removed with everything in it afterwards."""
    _swept()
    job = Path(tempfile.mkdtemp(prefix=f"{JOB_PREFIX}{os.getpid()}-"))
    box = Sandbox(job, limits, mode=mode)
    try:
        box.disk = box.mode == "root" and mount_tmpfs(job, limits.disk_mb)
        os.chmod(job, 0o711)
        for name, mode_bits in (("ws", 0o755), ("root", 0o700), ("hidden", 0o755)):
            (job / name).mkdir(mode=mode_bits)
        if box.disk:  # the instructor's tests do not share the student's disk
            mount_tmpfs(box.hidden, HIDDEN_MB)
        box.give(box.workspace)
        yield box
    finally:
        if box.disk:
            unmount(job)
        remove_tree(job)


def _own_process_count() -> int:
    uid = os.getuid()
    return sum(1 for p in Path("/proc").iterdir() if p.name.isdigit() and _owner(p) == uid)


def _owner(path: Path) -> int | None:
    try:
        return path.stat().st_uid
    except OSError:
        return None


def remove_job_folders(pid: int) -> None:
    """Remove what is left of the job folders of grading process ``pid`` (killed, so its
    private tmpfs is gone and only the folder it was mounted on, or an unmounted tree, is)."""
    for folder in Path(tempfile.gettempdir()).glob(f"{JOB_PREFIX}{pid}-*"):
        remove_tree(folder)
