"""A warm lint run replayed: an earlier run's report shown again while nothing it read changed.

A run of ``pkgtool lint`` on folders, with the cache on and nothing to fix, records what it
read (:class:`Witness`): every folder it listed (discovery's walk, each package's files, the
workspace index, pkgtool's own code) with each entry in it, the pyproject.toml files the
settings come from or their absence, and the interpreter's site-packages folders. The next run
with the same command line, folder, interpreter, pkgtool and colour looks at each of them again
(one ``stat`` each, less than listing them) and, when every one is as recorded, prints the
recorded report and exits with the recorded code: nothing is read, indexed or checked. When
only the contents of files changed (every folder is as recorded), the run goes on, but the
folders are not listed again: their entries come from the record, with the files' statuses
just examined (:data:`Listings`), and so do the outcomes of the packages whose files all kept
their times (:class:`Hint`): only the packages holding a changed file are looked up in the lint
cache, and checked when it has no entry for them.

Folders are compared by change and modification time (``st_ctime_ns``: adding, removing or
renaming an entry, or a permission change, sets it, and nothing can set it back; Windows gives
the creation time there, and its modification time tells), files by size, modification and
change time. A record is not kept when one of those times is too close to the start of the run
(:data:`SETTLED_NS`, :data:`FINE_SETTLED_NS`): a later change within the file system's time
granularity would be invisible; the next run records again. A folder holding a symbolic link is
always listed (what the link points to may change without the folder changing).

Four kinds of JSON files in ``lint/``, each written atomically and starting with a CRC-32 of
its content (a damaged or foreign one is ignored and replaced), the newest :data:`KEPT` of each
kept: ``run-<hash of the stamp>.json`` (the times and what was shown),
``layout-<check>.json`` (the folders, their entries, the other files and absent paths: written
once, shared by the records of later runs that read the same), ``walk-<check>.json`` (the
packages discovery found and each one's files, for :meth:`Witness.hint`) and
``outcomes-<check>.json`` (each package's name, findings, workspace-index entry and a hash of
its files' times, with one of everything else the run read).
"""

from __future__ import annotations

import binascii
import json
import os
import sys
import time
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from itertools import accumulate
from operator import attrgetter
from pathlib import Path
from typing import TYPE_CHECKING, Any, NamedTuple
from pkgtool.cache import Shown
from pkgtool.lazy_regex import lazy_pattern

if TYPE_CHECKING:
    from pkgtool.findings import Finding
    from pkgtool.model.context import WorkspacePackage
    from pkgtool.model.files import Scan
    from pkgtool.workspace import Discovery

    Outcome = tuple[str, list[Finding]]
    """A package's name and findings."""

SCHEMA = "pkgtool-lint-replay-4"
SETTLED_NS = 2_000_000_000
"""Times this close to a record's are not trusted on a file system with coarse times (FAT keeps
two seconds, HFS+ one, exFAT ten milliseconds): a later change within the same tick would not
show."""
FINE_SETTLED_NS = 100_000_000
"""The same on a file system with fine times (ext4, XFS, Btrfs, tmpfs, APFS, NTFS: nanoseconds
or a clock tick of a few milliseconds)."""
_COARSE_NS = 10_000_000
"""A change time that is a whole number of these comes from a coarse file system (on a fine
one, the chance is one in ten million): the times changed lately tell which kind holds them."""
KEPT = 16
"""Records kept per cache folder (one per command line, folder and colour)."""
_PREFIX = "run-"
_LAYOUT_PREFIX = "layout-"
_WALK_PREFIX = "walk-"
_OUTCOMES_PREFIX = "outcomes-"
_SETTINGS_FILE = "pyproject.toml"
"""Where settings come from (:mod:`pkgtool.config`): one in a package may set its neighbours'."""
_CHECK = lazy_pattern("[0-9a-f]{8}")
_TIMES = attrgetter("st_size", "st_mtime_ns", "st_ctime_ns")
"""What a record compares of each folder and file."""
_FOLDER_TIMES = attrgetter("st_mtime_ns", "st_ctime_ns")
"""What tells a folder's entries changed: the change time, and the modification time on
Windows (where ``st_ctime`` is when the folder was created)."""
_CHANGED = attrgetter("st_mtime_ns" if os.name == "nt" else "st_ctime_ns")
_SIZE_TIME = attrgetter("st_size", "st_mtime_ns")
"""A file's ``[size, mtime_ns]`` as :func:`pkgtool.model.files.scan` gives it."""


Positions = dict[str, tuple[list[str], list[int]]]
"""Each package's files (by folder) and their places in the statuses :func:`_now` takes."""


class Hint(NamedTuple):
    """What the record a run started from tells of this run (:meth:`Witness.hint`)."""

    found: Discovery
    """What discovery finds."""
    scans: dict[Path, Scan]
    """Each package's files with their sizes and times."""
    reused: dict[Path, Outcome]
    """The outcomes of the packages whose files are as they were, while nothing outside the
    packages changed: valid as long as the others still show the workspace the same."""
    index: dict[Path, WorkspacePackage]
    """Every package's workspace-index entry as it was (empty when nothing is reused)."""


class RecordedEntry:
    """A folder entry as a record saw it, standing in for an :class:`os.DirEntry` (the
    listing of a folder whose change time shows it unchanged)."""

    __slots__ = ("name", "path", "_status")

    def __init__(self, name: str, path: str, status: os.stat_result | None) -> None:
        self.name = name
        self.path = path
        self._status = status
        """The file's status as examined before the run; None for a folder."""

    def is_dir(self, *, follow_symlinks: bool = True) -> bool:
        return self._status is None

    def is_file(self, *, follow_symlinks: bool = True) -> bool:
        return self._status is not None

    def is_symlink(self) -> bool:
        return False  # a folder holding a link is never given from a record

    def stat(self, *, follow_symlinks: bool = True) -> os.stat_result:
        if self._status is None:
            raise OSError(f"{self.path} is a folder")  # never asked: lists call stat on files
        return self._status


class _Folder(NamedTuple):
    status: os.stat_result
    files: list[str]
    statuses: list[os.stat_result]
    folders: list[str]
    linked: bool
    """Some entry is a symbolic link: what it is may change without the folder changing."""


class Listings(Mapping[str, "tuple[os.stat_result, list[RecordedEntry]]"]):
    """The folders of a record that hold no link: path -> (status, entries), with the
    statuses :func:`replayed` just examined; entries are made when a folder is asked for."""

    def __init__(self, layout: dict[str, Any], statuses: list[os.stat_result],
                 times: list[tuple[int, int, int]], outcomes: str | None = None) -> None:
        self.layout = layout
        """The record's layout (its folders and their entries, its other files, its absent
        paths), which a run that lists nothing else records again as it is."""
        self.statuses = statuses
        """Every folder's status then its files', in the layout's order, then the other
        files'."""
        self.times = times
        """What a record compares of each of those statuses (:data:`_TIMES`)."""
        self.outcomes = outcomes
        """The check of the record's outcomes file, if it has one."""
        self._at: dict[str, tuple[int, list[str], list[str]]] = {}
        self._made: dict[str, tuple[os.stat_result, list[RecordedEntry]]] = {}
        folders = layout["folders"]
        for (folder, files, subfolders, linked), position in zip(
                folders, _starts(len(files) for _, files, _, _ in folders)):
            if not linked:
                self._at[folder] = (position, files, subfolders)

    def __getitem__(self, folder: str) -> tuple[os.stat_result, list[RecordedEntry]]:
        made = self._made.get(folder)
        if made is None:
            position, files, subfolders = self._at[folder]
            base = _inside(folder)
            found = self.statuses[position + 1:position + 1 + len(files)]
            made = self._made[folder] = (self.statuses[position], [
                *(RecordedEntry(name, base + name, status) for name, status in zip(files, found)),
                *(RecordedEntry(name, base + name, None) for name in subfolders)])
        return made

    def folder(self, folder: str) -> _Folder:
        """What :class:`Witness` keeps of the known ``folder`` (without looking at entries)."""
        position, files, subfolders = self._at[folder]
        return _Folder(self.statuses[position], files,
                       self.statuses[position + 1:position + 1 + len(files)], subfolders, False)

    def __contains__(self, folder: object) -> bool:
        return folder in self._at

    def __iter__(self) -> Iterator[str]:
        return iter(self._at)

    def __len__(self) -> int:
        return len(self._at)


class Witness:
    """What a lint run read, gathered while it runs (the argument of
    :func:`pkgtool.workspace.witnessed`), then :meth:`keep` what it showed."""

    def __init__(self, folder: Path, stamp: list[Any], known: Listings | None = None) -> None:
        from pkgtool.cache import prepare

        prepare(folder)  # now: made later, it would change a folder the run lists
        self.folder = folder / "lint"
        self.stamp = stamp
        self.taken_ns = time.time_ns()
        self.folders: dict[str, _Folder] = {}
        self.files: dict[str, os.stat_result] = {}
        self.absent: set[str] = set()
        self.replayable = True
        """False once the run read something this record cannot vouch for."""
        self.known = known
        """Folders whose entries an earlier record gives (:func:`replayed`)."""
        self.relayout = False
        """Write the layout again: some folder was listed, not known, or its walk is missing."""
        self.hinted = False
        """The run took what it would find from the record (:meth:`hint`): every known
        folder counts as listed."""
        self.walked: tuple[Discovery, Mapping[Path, Scan]] | None = None
        """What the run found and the files of each package (:meth:`found`)."""
        self.positions: Positions | None = None
        """Where each package's files stand in the statuses of the known layout."""
        self.outcomes: dict[str, Outcome] | None = None
        """Each package's outcome (:meth:`checked`)."""
        self.index: Mapping[Path, WorkspacePackage] = {}
        """The workspace index the run checked them with (:meth:`checked`)."""
        self.recorded: dict[str, tuple[Outcome, list[Any]]] = {}
        """The outcomes :meth:`hint` gave for reuse, by package, with their rows in the
        record's outcomes file (written again as they are when the run used them)."""
        self.package_times: tuple[int, dict[str, int]] | None = None
        """:func:`_package_times` of the known layout's statuses, once worked out."""

    def hint(self) -> Hint | None:
        """What the record this run started from tells: its folders are as recorded, so
        walking them would find the same packages and files, and the packages whose files
        are as they were need no check (None when the record cannot tell)."""
        if self.known is None or len(self.known) != len(self.known.layout["folders"]):
            return None  # a folder holds a link
        from pkgtool.workspace import Discovery

        try:
            walked = _read(self.folder / _walk_name(self.known.layout["id"]))
            roots = {root: Path(root) for root in walked["packages"]}
            found = Discovery(tuple(roots.values()), (), tuple(walked["empty"]))
            self.positions = {root: (paths, places) for root, paths, places in walked["scans"]}
            reused, index = self._recorded(roots)
            statuses = self.known.statuses
            scans = {roots[root]: [(path, list(_SIZE_TIME(statuses[at])))
                                   for path, at in zip(paths, places, strict=True)]
                     for root, (paths, places) in self.positions.items()
                     if roots[root] not in reused}  # the others are not looked at
        except (OSError, ValueError, RecursionError, KeyError, TypeError, AttributeError,
                IndexError):
            self.relayout = True
            return None
        self.hinted = True
        return Hint(found, scans, reused, index)

    def _recorded(self, roots: Mapping[str, Path]
                  ) -> tuple[dict[Path, Outcome], dict[Path, WorkspacePackage]]:
        """The outcomes the record holds of the packages whose files did not change, and every
        package's index entry; none when something outside the packages changed (ValueError
        when the outcomes file is not intact)."""
        assert self.known is not None and self.positions is not None
        if self.known.outcomes is None:
            return {}, {}
        from pkgtool.cache.serial import decode, index_entry
        from pkgtool.findings import Finding

        recorded = _read(self.folder / _outcomes_name(self.known.outcomes), self.known.outcomes)
        others, times = _package_times(self.positions, self.known.times)
        self.package_times = others, times
        if recorded["others"] != others:
            return {}, {}
        reused: dict[Path, Outcome] = {}
        index: dict[Path, WorkspacePackage] = {}
        for row in recorded["packages"]:
            root, recorded_times, name, findings, entry = row
            package = index_entry(entry)
            if package is None or not isinstance(name, str):
                raise ValueError("not an outcome")
            index[roots[root]] = package
            if times[root] == recorded_times:
                found = decode(findings)
                if not all(isinstance(finding, Finding) for finding in found):
                    raise ValueError("not findings")
                reused[roots[root]] = outcome = (name, found)
                self.recorded[root] = outcome, row
        return reused, index

    def checked(self, outcomes: dict[str, Outcome] | None,
                index: Mapping[Path, WorkspacePackage]) -> None:
        """Each package's outcome (None when some package could not be checked) and the
        workspace index the run checked them with, for the next run to reuse."""
        self.outcomes = outcomes
        self.index = index

    def found(self, discovery: Discovery, scans: Mapping[Path, Scan]) -> None:
        """The run's discovery and the files of its packages (recorded for :meth:`hint`)."""
        self.walked = discovery, scans

    def __call__(self, folder: str, status: os.stat_result | None,
                 entries: list[os.DirEntry[str]] | list[RecordedEntry]) -> None:
        """A folder was listed: remember its status and every entry in it."""
        if self.known is not None and folder in self.known:
            self.folders[folder] = self.known.folder(folder)
            return
        self.relayout = True
        if status is None:
            self.absent.add(folder)
            return
        files: list[str] = []
        statuses: list[os.stat_result] = []
        folders: list[str] = []
        linked = False
        for entry in entries:
            try:
                linked = linked or entry.is_symlink()
                if entry.is_file():
                    statuses.append(entry.stat())
                    files.append(entry.name)
                elif entry.is_dir():
                    folders.append(entry.name)
                else:  # a broken link, which a later file may mend
                    self.absent.add(entry.path)
            except OSError:
                self.absent.add(entry.path)
        self.folders[folder] = _Folder(status, files, statuses, folders, linked)

    def paths(self, paths: Iterable[Path]) -> None:
        """Files (or their absence) the run looked at; those in a folder it listed are known
        by that folder (its change time tells when one appears or goes)."""
        for path in paths:
            folder = os.path.dirname(path)
            if folder in self.folders or self.hinted and folder in (self.known or ()):
                continue
            try:
                self.files[os.fspath(path)] = os.stat(path)
            except OSError:
                self.absent.add(os.fspath(path))

    def keep(self, shown: Shown) -> None:
        """Record ``shown`` for the next run with this stamp (nothing when it is not
        replayable, something changed too recently, or the cache cannot be written)."""
        if not self.replayable or not self.folder.is_dir():
            return
        if self.hinted and self.known is not None and \
                not _settled(list(map(_CHANGED, self.known.statuses)), self.taken_ns):
            return  # the usual case after an edit, known before working out the record
        try:
            for folder in site_folders():
                self.folders[folder] = _Folder(os.stat(folder), [], [], [], False)
        except OSError:
            return
        layout = self._known_layout()
        if layout is None and self.hinted:
            assert self.known is not None
            self.folders = {**{path: self.known.folder(path) for path in self.known},
                            **self.folders}
        order = [path for path, *_ in layout["folders"]] if layout else list(self.folders)
        if layout and self.hinted:
            statuses, times = self._known_statuses(layout)
        else:
            statuses = [s for path in order for s in (self.folders[path].status,
                                                      *self.folders[path].statuses)]
            times = list(map(_TIMES, statuses))
        statuses += self.files.values()
        times += map(_TIMES, self.files.values())
        if not _settled(list(map(_CHANGED, statuses)), self.taken_ns):
            return
        if layout is None:
            self.positions = self.package_times = None  # the known layout's, not these
            self.recorded = {}
            layout = {"schema": SCHEMA,
                      "folders": [[path, folder.files, folder.folders, folder.linked]
                                  for path, folder in self.folders.items()],
                      "files": list(self.files), "absent": sorted(self.absent),
                      "folder_times": hash(tuple(_FOLDER_TIMES(self.folders[path].status)
                                                 for path in order))}
            layout["id"] = _write(self.folder, _layout_name, layout)
            self.positions = self._positions(order)
            if self.walked is not None and self.positions is not None:
                _write(self.folder, lambda _: _walk_name(layout["id"]), {
                    "packages": [str(root) for root in self.walked[0].packages],
                    "empty": list(self.walked[0].empty),
                    "scans": [[root, *files] for root, files in self.positions.items()]})
        record = {"schema": SCHEMA, "stamp": self.stamp, "layout": layout["id"],
                  "times": hash(tuple(times)), "entries": len(times), "shown": list(shown),
                  "outcomes": self._write_outcomes(times)}
        _write(self.folder, lambda _: _name(self.stamp), record)
        _prune(self.folder)

    def _known_statuses(self, layout: dict[str, Any]
                        ) -> tuple[list[os.stat_result], list[tuple[int, int, int]]]:
        """The statuses of the known ``layout``'s folders and their files, as they were
        before the run (its other files are looked at by the run), and their times."""
        assert self.known is not None
        end = len(self.known.statuses) - len(layout["files"])
        return self.known.statuses[:end], self.known.times[:end]

    def _positions(self, order: list[str]) -> Positions | None:
        """Each package's files and their places in the statuses a check of the layout takes
        (None when the run did not scan every package, or some file is not in the layout)."""
        if self.walked is None or len(self.walked[0].packages) != len(self.walked[1]):
            return None  # some package's files were not looked at
        places: dict[str, int] = {}
        for path, at in zip(order, _starts(len(self.folders[path].files) for path in order)):
            places.update((_inside(path) + name, at + 1 + number)
                          for number, name in enumerate(self.folders[path].files))
        try:
            return {str(root): ([path for path, _ in scanned],
                                [places[f"{root}/{path}"] for path, _ in scanned])
                    for root, scanned in self.walked[1].items()}
        except KeyError:
            return None

    def _write_outcomes(self, times: list[tuple[int, int, int]]) -> str | None:
        """Write each package's outcome with what tells whether its files changed; the file's
        check (None when some package has no outcome or its files are not all known)."""
        if self.outcomes is None or self.positions is None or \
                set(self.outcomes) != set(self.positions):
            return None
        from pkgtool.cache.serial import encode, index_record

        others, each = self.package_times or _package_times(self.positions, times)
        packages = [self.recorded[root][1] if self.recorded.get(root, (None,))[0] is outcome
                    else [root, each[root], outcome[0], encode(outcome[1]),
                          index_record(self.index[Path(root)])]
                    for root, outcome in self.outcomes.items()]
        return _write(self.folder, _outcomes_name, {"others": others, "packages": packages})

    def _known_layout(self) -> dict[str, Any] | None:
        """The layout of the record this run started from when this run read exactly the
        folders, files and absent paths it holds (written once, kept by later records)."""
        if self.known is None or self.relayout:
            return None
        layout = self.known.layout
        if self.hinted:  # every known folder counts as listed: were the others known?
            listed = all(path in self.known for path in self.folders)
        else:
            listed = len(layout["folders"]) == len(self.folders) and \
                all(path in self.folders for path, *_ in layout["folders"])
        if not listed or layout["files"] != list(self.files) or \
                layout["absent"] != sorted(self.absent):
            return None
        return layout


def stamp(arguments: dict[str, Any], colour: bool) -> list[Any]:
    """What besides the files decides a run's report: ``arguments`` (the command line as
    :func:`pkgtool.cli_lint_run.lint_call` got it, JSON-able), the folder it runs in, the
    colour, the interpreter and pkgtool."""
    import pkgtool

    return [SCHEMA, pkgtool.__version__, sys.executable, sys.version, os.getcwd(), colour,
            sorted(arguments.items()), _source_stamp(Path(pkgtool.__file__).parent)]


def _source_stamp(code: Path) -> list[Any]:
    """For pkgtool run from a source tree (an editable install, not ``site-packages``), the
    sizes and times of its files: an edited rule must not replay an older report. A release
    is told apart by its version alone."""
    if "site-packages" in code.parts or "dist-packages" in code.parts:
        return []
    return code_files(code)


def code_files(code: Path) -> list[list[Any]]:
    """The files of pkgtool's code folder ``code``, each with its size and time."""
    from pkgtool.model.files import scan

    return [[path, *size_time] for path, size_time in scan(code)]


class Record(NamedTuple):
    """A run's record, read and checked (:func:`recorded`), not yet compared with the files."""

    record: dict[str, Any]
    entries: int
    """How many folders and files comparing it with them looks at (0: not recorded)."""


def recorded(folder: Path, stamp: list[Any]) -> Record | None:
    """The record in the cache ``folder`` of the run with ``stamp``, when intact (a small file:
    its layout, the large part, is read by :func:`replayed`)."""
    try:
        record = _read(folder / "lint" / _name(stamp))
        if record["schema"] != SCHEMA or record["stamp"] != json.loads(json.dumps(stamp)) or \
                not _CHECK.fullmatch(record["layout"]):
            return None
        entries = record.get("entries")
        return Record(record, entries if isinstance(entries, int) else 0)
    except (OSError, ValueError, RecursionError, KeyError, TypeError, AttributeError):
        return None


def replayed(folder: Path, found: Record | None) -> Shown | Listings | None:
    """The run ``found`` (the :func:`recorded` one of the cache ``folder``) records, when
    everything it read is as it was; else, when only the contents of files changed, what its
    folders hold (the next run need not list them); else None."""
    if found is None:
        return None
    record = found.record
    try:
        layout = _read(folder / "lint" / _layout_name(record["layout"]), record["layout"])
        if layout["schema"] != SCHEMA or any(map(os.path.exists, layout["absent"])):
            return None
        layout["id"] = record["layout"]
        statuses, changed = _now(layout["folders"], layout["files"])
        if hash(tuple(changed)) != layout["folder_times"]:
            return None
        times = list(map(_TIMES, statuses))
        if hash(tuple(times)) != record["times"]:
            outcomes = record.get("outcomes")
            return Listings(layout, statuses, times, outcomes if isinstance(outcomes, str) and
                            _CHECK.fullmatch(outcomes) else None)
        code, report, messages = record["shown"]
        if isinstance(code, int) and isinstance(report, str) and isinstance(messages, list) \
                and all(isinstance(m, str) for m in messages):
            return Shown(code, report, messages)
    except (OSError, ValueError, RecursionError, KeyError, TypeError, AttributeError):
        pass
    return None


def _now(folders: list[list[Any]], files: list[str]
         ) -> tuple[list[os.stat_result], list[tuple[int, int]]]:
    """The status now of every folder of a record, each followed by its files', then of its
    other files; and the times of the folders (OSError for a vanished one)."""
    stat = os.stat
    statuses: list[os.stat_result] = []
    changed: list[tuple[int, int]] = []
    for folder, names, _, _ in folders:
        status = stat(folder)
        statuses.append(status)
        changed.append(_FOLDER_TIMES(status))
        base = _inside(folder)
        statuses += [stat(base + name) for name in names]
    statuses += map(stat, files)
    return statuses, changed


def _package_times(positions: Positions, times: list[tuple[int, int, int]]
                   ) -> tuple[int, dict[str, int]]:
    """What tells whether anything besides the packages' files changed (the :data:`_TIMES` of
    everything else, and of the packages' pyproject.toml files), and each package's files."""
    inside: set[int] = set()
    settings: list[tuple[int, int, int]] = []
    each: dict[str, int] = {}
    for root, (paths, places) in positions.items():
        inside.update(places)
        each[root] = hash(tuple(map(times.__getitem__, places)))
        if _SETTINGS_FILE in "\n".join(paths):  # rare: look closer
            settings += [times[at] for path, at in zip(paths, places)
                         if path == _SETTINGS_FILE or path.endswith(f"/{_SETTINGS_FILE}")]
    others = [status for at, status in enumerate(times) if at not in inside]
    return hash((*others, *settings)), each


def _starts(counts: Iterable[int]) -> Iterator[int]:
    """Where each folder's status stands in the statuses :func:`_now` takes, from the number
    of files of each folder in order (each folder's status comes before its files')."""
    return accumulate((1 + count for count in counts), initial=0)


def _inside(folder: str) -> str:
    """``folder`` as the prefix of the paths of its entries."""
    return folder if folder.endswith("/") else f"{folder}/"


def _settled(changes: list[int], taken_ns: int) -> bool:
    """True when every change time is old enough at ``taken_ns`` for a later change to show
    (see :data:`SETTLED_NS`)."""
    recent = [t for t in changes if t >= taken_ns - SETTLED_NS]  # few: those just changed
    return not recent or (max(recent) < taken_ns - FINE_SETTLED_NS and
                          all(t % _COARSE_NS for t in recent))


def site_folders() -> Sequence[str]:
    """The interpreter's site-packages folders: installing or removing a distribution (a
    newer pyflakes or lxml) changes them."""
    return [entry for entry in sys.path if entry.endswith("-packages") and os.path.isdir(entry)]


def _name(stamp: list[Any]) -> str:
    text = json.dumps(stamp, separators=(",", ":"))
    return f"{_PREFIX}{binascii.crc32(text.encode()):08x}.json"


def _write(folder: Path, name: Callable[[str], str], data: dict[str, Any]) -> str:
    """Write ``data`` as JSON after its check (a CRC-32 of the JSON) to the file ``name``
    gives for the check; the check."""
    from pkgtool.cache import write_atomically

    text = json.dumps(data, separators=(",", ":"))
    check = f"{binascii.crc32(text.encode()):08x}"
    write_atomically(folder, name(check), f"{check}\n{text}")
    return check


def _read(path: Path, check: str | None = None) -> Any:
    """What :func:`_write` wrote to ``path`` (with the ``check`` given, if any); ValueError
    when the file does not hold it intact."""
    with open(path, "rb") as stream:
        found, _, text = stream.read().partition(b"\n")
    if not _CHECK.fullmatch(found.decode("ascii", "replace")) or \
            f"{binascii.crc32(text):08x}".encode() != found or \
            (check is not None and found.decode() != check):
        raise ValueError(f"{path} is damaged")
    return json.loads(text)


def _layout_name(layout_id: str) -> str:
    return f"{_LAYOUT_PREFIX}{layout_id}.json"


def _walk_name(layout_id: str) -> str:
    return f"{_WALK_PREFIX}{layout_id}.json"


def _outcomes_name(check: str) -> str:
    return f"{_OUTCOMES_PREFIX}{check}.json"


def _prune(folder: Path) -> None:
    """Keep the newest :data:`KEPT` records, layouts, walks and outcomes."""
    try:
        for prefix in (_PREFIX, _LAYOUT_PREFIX, _WALK_PREFIX, _OUTCOMES_PREFIX):
            kept = sorted((entry.stat().st_mtime_ns, entry.path) for entry in os.scandir(folder)
                          if entry.name.startswith(prefix))
            for _, path in kept[:-KEPT]:
                os.unlink(path)
    except OSError:
        pass
