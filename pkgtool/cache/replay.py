"""A warm lint run replayed: an earlier run's report shown again while nothing it read changed.

A run of ``pkgtool lint`` on folders, with the cache on and nothing to fix, records what it
read (:class:`Witness`): every folder it listed (discovery's walk, each package's files, the
workspace index, pkgtool's own code) with each file in it, the pyproject.toml files the
settings come from or their absence, and the interpreter's site-packages folders. The next run
with the same command line, folder, interpreter, pkgtool and colour looks at each of them again
(one ``stat`` each, less than listing them) and, when every one is as recorded, prints the
recorded report and exits with the recorded code: nothing is read, indexed or checked.

Folders are compared by change time (``st_ctime_ns``: adding, removing or renaming an entry,
or a permission change, sets it, and nothing can set it back), files by size, modification and
change time. A record is never replayed when one of those times is less than
:data:`SETTLED_NS` older than the record (a later change within the file system's time
granularity would be invisible); the next run records again. Records are JSON files written
atomically (``lint/run-<hash>.json``, the newest :data:`KEPT` kept); one that cannot be read or
is not pkgtool's is ignored and replaced.
"""

from __future__ import annotations

import binascii
import json
import os
import sys
import time
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import Any, NamedTuple

SCHEMA = "pkgtool-lint-replay-1"
SETTLED_NS = 2_000_000_000
"""Times this close to a record's are not trusted (see the module's docstring)."""
KEPT = 16
"""Records kept per cache folder (one per command line, folder and colour)."""
_PREFIX = "run-"


class Shown(NamedTuple):
    """What a lint run showed: its exit code, its report and its messages (to stderr)."""

    code: int
    report: str
    messages: list[str]


class Witness:
    """What a lint run read, gathered while it runs (the argument of
    :func:`pkgtool.workspace.witnessed`), then :meth:`keep` what it showed."""

    def __init__(self, folder: Path, stamp: list[Any]) -> None:
        from pkgtool.cache import prepare

        prepare(folder)  # now: made later, it would change a folder the run lists
        self.folder = folder / "lint"
        self.stamp = stamp
        self.taken_ns = time.time_ns()
        self.folders: dict[str, tuple[int, list[str], list[int]]] = {}
        """Folder -> its change time, its files' names and their times (three each)."""
        self.files: dict[str, list[int]] = {}
        self.absent: set[str] = set()
        self.replayable = True
        """False once the run read something this record cannot vouch for."""

    def __call__(self, folder: str, status: os.stat_result | None,
                 entries: list[os.DirEntry[str]]) -> None:
        """A folder was listed: remember its time and every file in it."""
        if status is None:
            self.absent.add(folder)
            return
        names: list[str] = []
        times: list[int] = []
        for entry in entries:
            try:
                if entry.is_file():
                    times += _file_times(entry.stat())
                    names.append(entry.name)
                elif not entry.is_dir():  # a broken link, which a later file may mend
                    self.absent.add(entry.path)
            except OSError:
                self.absent.add(entry.path)
        self.folders[folder] = (status.st_ctime_ns, names, times)

    def paths(self, paths: Iterable[Path]) -> None:
        """Files (or their absence) the run looked at outside the folders it listed."""
        for path in paths:
            try:
                self.files[os.fspath(path)] = _file_times(os.stat(path))
            except OSError:
                self.absent.add(os.fspath(path))

    def keep(self, shown: Shown) -> None:
        """Record ``shown`` for the next run with this stamp (nothing when it is not
        replayable, something changed too recently, or the cache cannot be written)."""
        if not self.replayable or not self.folder.is_dir():
            return
        try:
            for folder in site_folders():
                self.folders[folder] = (os.stat(folder).st_ctime_ns, [], [])
        except OSError:
            return
        changes = [changed for changed, _, _ in self.folders.values()]
        changes += [t for _, _, files in self.folders.values() for t in files[2::3]]
        changes += [stats[2] for stats in self.files.values()]
        if max(changes, default=0) >= self.taken_ns - SETTLED_NS:
            return
        times = [t for changed, _, files in self.folders.values() for t in (changed, *files)]
        times += [t for stats in self.files.values() for t in stats]
        record = {"schema": SCHEMA, "stamp": self.stamp,
                  "folders": [[f, names] for f, (_, names, _) in self.folders.items()],
                  "files": list(self.files), "absent": sorted(self.absent),
                  "times": hash(tuple(times)), "shown": list(shown)}
        from pkgtool.cache import write_atomically

        write_atomically(self.folder, _name(self.stamp), json.dumps(record, separators=(",", ":")))
        _prune(self.folder)


def stamp(arguments: dict[str, Any], colour: bool) -> list[Any]:
    """What besides the files decides a run's report: ``arguments`` (the command line as
    :func:`pkgtool.cli_lint_run.lint_call` got it, JSON-able), the folder it runs in, the
    colour, the interpreter and pkgtool."""
    import pkgtool

    return [SCHEMA, pkgtool.__version__, sys.executable, sys.version, os.getcwd(), colour,
            sorted(arguments.items())]


def replayed(folder: Path, stamp: list[Any]) -> Shown | None:
    """The run recorded in the cache ``folder`` with ``stamp``, when everything it read is as
    it was; None otherwise."""
    try:
        with open(folder / "lint" / _name(stamp), encoding="utf-8") as stream:
            record = json.load(stream)
        if record["schema"] != SCHEMA or record["stamp"] != json.loads(json.dumps(stamp)) or \
                hash(tuple(_times_now(record["folders"], record["files"]))) != record["times"] \
                or any(map(os.path.exists, record["absent"])):
            return None
        code, report, messages = record["shown"]
        if isinstance(code, int) and isinstance(report, str) and isinstance(messages, list) \
                and all(isinstance(m, str) for m in messages):
            return Shown(code, report, messages)
    except (OSError, ValueError, RecursionError, KeyError, TypeError, AttributeError):
        pass
    return None


def _times_now(folders: list[list[Any]], files: list[str]) -> list[int]:
    """The times :meth:`Witness.keep` hashes, as they are now (OSError for a vanished one)."""
    stat = os.stat
    times: list[int] = []
    for folder, names in folders:
        times.append(stat(folder).st_ctime_ns)
        for name in names:
            now = stat(f"{folder}/{name}")
            times += (now.st_size, now.st_mtime_ns, now.st_ctime_ns)
    for path in files:
        now = stat(path)
        times += (now.st_size, now.st_mtime_ns, now.st_ctime_ns)
    return times


def _file_times(status: os.stat_result) -> list[int]:
    return [status.st_size, status.st_mtime_ns, status.st_ctime_ns]


def site_folders() -> Sequence[str]:
    """The interpreter's site-packages folders: installing or removing a distribution (a
    newer pyflakes or lxml) changes them."""
    return [entry for entry in sys.path if entry.endswith("-packages") and os.path.isdir(entry)]


def _name(stamp: list[Any]) -> str:
    text = json.dumps(stamp, separators=(",", ":"))
    return f"{_PREFIX}{binascii.crc32(text.encode()):08x}.json"


def _prune(folder: Path) -> None:
    """Keep the newest :data:`KEPT` records."""
    try:
        records = sorted((entry.stat().st_mtime_ns, entry.path) for entry in os.scandir(folder)
                         if entry.name.startswith(_PREFIX))
        for _, path in records[:-KEPT]:
            os.unlink(path)
    except OSError:
        pass
