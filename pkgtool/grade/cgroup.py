"""A cgroup per sandboxed step, nested under our own: process-count and memory caps that hold.

cgroup v1 (one hierarchy per controller) and v2 (one unified hierarchy, when our cgroup
delegates ``pids`` and ``memory`` to its children) are both handled; without write access
there is no cgroup and the sandbox relies on rlimits alone. A step's cgroup is named
``pkgtool-<pid>-<n>`` after the grading process that made it: when that process is gone
(killed, even by SIGKILL), :func:`sweep` kills whatever is left in its cgroups and removes
them, and every grading run sweeps those of dead processes when it starts.
"""

from __future__ import annotations

import functools
import itertools
import os
import signal
import time
from pathlib import Path

from pkgtool.records import record
from pkgtool.lazy_regex import lazy_pattern

# controller -> (limit file, events file, event counted), per cgroup version
_FILES = {
    1: {"pids": ("pids.max", "pids.events", "max"),
        "memory": ("memory.limit_in_bytes", "memory.oom_control", "oom_kill")},
    2: {"pids": ("pids.max", "pids.events", "max"),
        "memory": ("memory.max", "memory.events", "oom_kill")},
}
_ROOT = Path("/sys/fs/cgroup")
_names = itertools.count()
_NAME = lazy_pattern(r"^pkgtool-(\d+)-\d+$")


@record
class JobCgroup:
    """One job's cgroup folders (controller -> folder) in cgroup ``version`` 1 or 2."""

    version: int
    folders: dict[str, Path]

    def procs_files(self) -> list[Path]:
        """The ``cgroup.procs`` files a process writes ``0`` to in order to join."""
        return sorted({folder / "cgroup.procs" for folder in self.folders.values()})

    def events(self) -> dict[str, int]:
        """How often each limit was hit: ``{"pids": n, "memory": n}``."""
        counts = {}
        for controller, folder in self.folders.items():
            _, events, key = _FILES[self.version][controller]
            counts[controller] = _counter(folder / events, key)
        return counts

    def kill_all(self) -> None:
        """SIGKILL every process left in the cgroup (v2: ``cgroup.kill``; v1: repeatedly,
        forks race the killer, ``pids.max`` bounds them)."""
        kill = self.folders["pids"] / "cgroup.kill"
        if self.version == 2 and kill.is_file():
            kill.write_text("1")
        for _ in range(50):
            pids = {int(p) for f in self.procs_files() for p in _read(f).split() if p.isdigit()}
            if not pids:
                return
            for pid in pids:
                try:
                    os.kill(pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
            time.sleep(0.02)

    def remove(self) -> None:
        """Kill what is left and delete the folders (quietly: the kernel may lag a moment)."""
        self.kill_all()
        for folder in set(self.folders.values()):
            for _ in range(50):
                try:
                    folder.rmdir()
                    break
                except FileNotFoundError:
                    break
                except OSError:
                    time.sleep(0.02)


def _read(path: Path) -> str:
    try:
        return path.read_text()
    except OSError:
        return ""


def _counter(path: Path, key: str) -> int:
    for line in _read(path).splitlines():
        name, _, value = line.partition(" ")
        if name == key and value.strip().isdigit():
            return int(value)
    return 0


def _own_paths() -> dict[str, str]:
    """Our cgroup per v1 controller (``pids``, ``memory``), and ``""`` for the v2 hierarchy."""
    paths = {}
    for line in _read(Path("/proc/self/cgroup")).splitlines():
        _, controllers, path = line.split(":", 2)
        for name in controllers.split(",") if controllers else [""]:
            paths[name] = path
    return paths


def _parents() -> tuple[int, dict[str, Path]] | None:
    own = _own_paths()
    if all((_ROOT / c).is_dir() and c in own for c in ("pids", "memory")):
        return 1, {c: _ROOT / c / own[c].lstrip("/") for c in ("pids", "memory")}
    if "" in own and (_ROOT / "cgroup.controllers").is_file():
        parent = _ROOT / own[""].lstrip("/")
        if {"pids", "memory"} <= set(_read(parent / "cgroup.subtree_control").split()):
            return 2, {"pids": parent, "memory": parent}
    return None


def sweep(pid: int | None = None) -> int:
    """Kill and remove the cgroups of grading process ``pid`` (default: of every dead one).

    Returns how many were removed.
    """
    found = _parents()
    if found is None or os.geteuid() != 0:
        return 0
    version, parents = found
    listed = [_listing(parent) for parent in set(parents.values())]
    names = {n for n in set.intersection(*listed) if _stale(n, pid)}  # ours: in every parent
    for name in names:
        JobCgroup(version, {c: p / name for c, p in parents.items()}).remove()
    return len(names)


def _listing(folder: Path) -> set[str]:
    try:
        return {entry.name for entry in os.scandir(folder) if entry.is_dir()}
    except OSError:
        return set()


def _stale(name: str, pid: int | None) -> bool:
    match = _NAME.match(name)
    if match is None:
        return False
    owner = int(match.group(1))
    if pid is not None:
        return owner == pid
    try:
        os.kill(owner, 0)
    except ProcessLookupError:
        return True
    except PermissionError:
        return False
    return False


def create_job_cgroup(*, max_pids: int, memory_bytes: int) -> JobCgroup | None:
    """A fresh cgroup with these caps, or None when this process may not create one."""
    found = _parents()
    if found is None or os.geteuid() != 0:
        return None
    version, parents = found
    name = f"pkgtool-{os.getpid()}-{next(_names)}"
    folders = {c: parent / name for c, parent in parents.items()}
    limits = {"pids": str(max_pids), "memory": str(memory_bytes)}
    try:
        for controller, folder in folders.items():
            folder.mkdir(exist_ok=True)
            (folder / _FILES[version][controller][0]).write_text(limits[controller])
    except OSError:
        JobCgroup(version, folders).remove()
        return None
    return JobCgroup(version, folders)


@functools.cache
def cgroups_available() -> bool:
    """True when this process can create job cgroups (probed once by creating one)."""
    probe = create_job_cgroup(max_pids=16, memory_bytes=64 * 1024 * 1024)
    if probe is None:
        return False
    probe.remove()
    return True
