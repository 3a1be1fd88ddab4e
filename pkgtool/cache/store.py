"""The cache on disk: one JSON entry per package, trusted only when its key matches exactly.

The entries live in :data:`PACKS` files, ``lint/packages-NN.json``, by a hash of the package's
folder (reading a few files is what makes a warm run of a large workspace fast, and after an
edit only the file holding the changed package's entry is written again); a run reads them
once, and the process that started the run writes those holding new entries once at the end,
each merged with what other runs wrote to it meanwhile.

The key of a package is a SHA-256 over: the cache schema, pkgtool's version and a fingerprint
of its installed code and data, the Python version and the installed distributions, the
package's effective settings (rule selection, severities, path ignores, target distribution),
the workspace index its rules read (every sibling package's folder, name, interfaces, their
message fields, Python packages and a digest of its setup files), and the path and content
hash of every file of the package. A file's content hash is reused from the entry when its
size and modification time are unchanged and it was last modified well before it was hashed
(so an edit within the file system's time granularity is never missed); otherwise the file is
read again.

A file is written to a temporary file and renamed into place, so concurrent runs never see
it half-written (the last one to finish keeps its own entries). An entry that cannot be read,
parsed or decoded, or whose key differs, is ignored and rewritten after linting; entries of
packages that no longer exist are dropped.
"""

from __future__ import annotations

import binascii
import contextlib
import json
import os
import sys
import time
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from pkgtool.cache import prepare, write_atomically
from pkgtool.cache.replay import code_files, site_folders
from pkgtool.cache.serial import BadEntry, decode, encode, index_entry, index_record
from pkgtool.config import Settings
from pkgtool.findings import Finding
from pkgtool.model.context import WorkspacePackage
from pkgtool.model.digest import sha256
from pkgtool.model.files import Scan, scan
from pkgtool.records import record


SCHEMA = "pkgtool-lint-cache-9"
PACKS = 16
"""The files in ``lint/`` the entries are spread over (by package folder): a run that checked
a few packages writes a few small files."""
Pack = tuple[tuple[int, int, int] | None, dict[str, Any]]
"""A file of ``lint/`` as a run read it: what tells whether it was replaced since (its inode,
modification time and size; None when it was missing), and its entries by package folder."""
_SETTLED_NS = 2_000_000_000
"""A file modified this long before it was hashed is trusted by size and time afterwards."""


@record
class Files:
    """What a package's files were when they were hashed: path -> [size, mtime_ns, sha256]."""

    stats: dict[str, list[Any]]
    taken_ns: int

    def digest(self) -> str:
        """The paths and contents of the files, as one hash."""
        listing = "\0".join(f"{path}\0{stat[2]}" for path, stat in sorted(self.stats.items()))
        return sha256(listing.encode("utf-8", "surrogateescape")).hexdigest()

    def unchanged(self, root: Path) -> bool:
        """True when the package has the same files, with the sizes and times they had when
        hashed."""
        now = scan(root)
        return len(now) == len(self.stats) and \
            all(self.stats.get(path, [])[:2] == size_time for path, size_time in now)


@record
class Lookup:
    """A package's key and files; ``hit`` holds (name, findings) when the entry was valid."""

    key: str
    files: Files
    digest: str
    """``files.digest()``: the recorded one while no file changed."""
    hit: tuple[str, list[Finding]] | None
    refresh: bool
    """The entry was valid but some file had to be hashed again: rewrite its times."""


Entry = dict[str, Any]
"""A package's cache entry as stored (JSON)."""


class LintCache:
    """The lint cache in ``folder`` for one run (one code version, one workspace).

    Opened before the workspace is indexed (:meth:`indexed` spares reading the packages whose
    files did not change), then :meth:`bind` to the run's workspace index before any lookup.
    """

    def __init__(self, folder: Path) -> None:
        self.folder = folder / "lint"
        self.base = folder
        self._packs: dict[str, Pack] = {}
        """The files of ``lint/`` read so far, each when an entry in it is first asked for."""
        self._fresh: dict[str, Entry] = {}
        self._code_key = _digest([SCHEMA, _code_fingerprint()])
        self._run_key = ""
        self._workspace: Mapping[Path, WorkspacePackage] = {}
        self._settings_keys: dict[int, tuple[Settings, str]] = {}
        self._probed: dict[Path, tuple[Scan, Files]] = {}
        self._looked: set[str] = set()
        """Packages looked up by this run: they exist (no need to ask before saving)."""
        """Packages :meth:`indexed` found as recorded: their scan and files."""

    def indexed(self, scans: Mapping[Path, Scan]) -> dict[Path, WorkspacePackage]:
        """The workspace-index entries recorded by this code with the packages whose files are
        all as they were then (the same paths, sizes and settled times): they need not be read
        again."""
        known = {}
        for root, scanned in scans.items():
            entry = self._entry_of(root)
            old = entry.get("files")
            if entry.get("code") != self._code_key or not isinstance(old, dict) or \
                    len(old) != len(scanned):
                continue
            files = _hash_files(root, old, entry.get("taken_ns"), False, scanned)
            if files is not None:  # every file as recorded: the lookup need not look again
                self._probed[root] = scanned, files
                package = index_entry(entry.get("index"))
                if package is not None:
                    known[root] = package
        return known

    def bind(self, workspace: Mapping[Path, WorkspacePackage]) -> None:
        """Key the lookups to this code and the run's ``workspace`` index."""
        self._workspace = workspace
        self._run_key = _digest([self._code_key, _workspace_key(workspace)])

    def lookup(self, root: Path, settings: Settings, *, read: bool = True,
               scanned: Scan | None = None) -> Lookup | None:
        """The key of the package at ``root`` and, when its entry is valid, the findings.

        With ``read`` False only sizes and times are looked at: None when some file would
        have to be read (a quick probe that leaves the reading to a worker process).
        ``scanned``: the package's :func:`scan`, when the caller made it already.
        """
        assert self._run_key, "bind() the cache to the workspace first"
        self._looked.add(str(root))
        entry = self._entry_of(root)
        old = entry.get("files") if isinstance(entry.get("files"), dict) else {}
        probed = self._probed.get(root)
        files = probed[1] if probed is not None and probed[0] is scanned else \
            _hash_files(root, old, entry.get("taken_ns"), read, scanned)
        if files is None:
            return None
        refresh = len(old) != len(files.stats) or \
            any(old.get(path) != stat for path, stat in files.stats.items())
        recorded = entry.get("digest")
        digest = recorded if not refresh and isinstance(recorded, str) else files.digest()
        key = _digest([self._run_key, self._settings_key(settings), digest])
        if entry.get("key") != key:
            return Lookup(key, files, digest, None, False)
        try:
            findings = decode(entry.get("findings"))
            name = entry.get("name")
            if not isinstance(name, str) or not isinstance(findings, list) or \
                    not all(isinstance(f, Finding) for f in findings):
                raise BadEntry("not a list of findings")
        except (BadEntry, RecursionError):
            return Lookup(key, files, digest, None, False)
        return Lookup(key, files, digest, (name, findings), refresh)

    def _entry_of(self, root: Path) -> Entry:
        """The stored entry of the package at ``root``; empty when there is none or it is not
        one (not a dict, or recorded for another folder)."""
        entry = self._pack(pack_of(str(root)))[1].get(str(root))
        return entry if isinstance(entry, dict) and entry.get("root") == str(root) else {}

    def _settings_key(self, settings: Settings) -> str:
        """The digest of ``settings`` (packages share a few settings objects: worked out once
        per object)."""
        known = self._settings_keys.get(id(settings))
        if known is None:
            known = self._settings_keys[id(settings)] = (
                settings, _digest(_settings_parts(settings)))
        return known[1]

    def entry(self, root: Path, lookup: Lookup, name: str, findings: list[Finding]
              ) -> Entry | None:
        """The entry recording ``findings`` for ``root`` (:meth:`keep` it in the process that
        saves); None when a file changed while the package was checked."""
        if not lookup.files.unchanged(root):
            return None
        package = self._workspace.get(root)
        return {"root": str(root), "key": lookup.key, "name": name, "code": self._code_key,
                "digest": lookup.digest,
                "index": index_record(package) if package is not None else None,
                "taken_ns": lookup.files.taken_ns, "files": lookup.files.stats,
                "findings": encode(findings)}

    def keep(self, entry: Entry) -> None:
        """Record ``entry`` for :meth:`save`."""
        self._fresh[entry["root"]] = entry

    def save(self) -> None:
        """Write the files holding kept entries, or (among the files this run read) entries of
        packages that no longer exist, atomically, each merged with the file as it is now."""
        if not self._fresh or not prepare(self.base):
            return
        with contextlib.suppress(OSError):
            os.unlink(self.folder / "packages.json")  # where pkgtool 0.1 kept every entry
        gone = {name for name, (_, pack) in self._packs.items()
                if any(root not in self._looked and not os.path.isdir(root) for root in pack)}
        for name in sorted(gone | {pack_of(root) for root in self._fresh}):
            path = self.folder / name
            identity, read = self._pack(name)
            others = read if _identity(path) == identity else _load(path)
            entries = {root: entry for root, entry in others.items()
                       if root not in self._fresh and os.path.isdir(root)}
            entries.update((root, entry) for root, entry in self._fresh.items()
                           if pack_of(root) == name)
            write_atomically(self.folder, name, json.dumps(
                {"schema": SCHEMA, "entries": entries}, separators=(",", ":")))

    def _pack(self, name: str) -> Pack:
        """The file ``name`` of ``lint/`` as this run first read it."""
        read = self._packs.get(name)
        if read is None:
            path = self.folder / name
            read = self._packs[name] = (_identity(path), _load(path))
        return read


def pack_of(root: str) -> str:
    """The name of the file in ``lint/`` holding the entry of the package at ``root``."""
    number = binascii.crc32(root.encode("utf-8", "surrogateescape")) % PACKS
    return f"packages-{number:02d}.json"


def _identity(path: Path) -> tuple[int, int, int] | None:
    """What tells whether the file at ``path`` was replaced (it never changes in place)."""
    try:
        stat = os.stat(path)
    except OSError:
        return None
    return stat.st_ino, stat.st_mtime_ns, stat.st_size


def _load(path: Path) -> dict[str, Any]:
    """The entries of the cache file by package root; none when it is missing or not ours."""
    try:
        with open(path, encoding="utf-8") as stream:
            pack = json.load(stream)
    except (OSError, ValueError, RecursionError):
        return {}
    if not isinstance(pack, dict) or pack.get("schema") != SCHEMA or \
            not isinstance(pack.get("entries"), dict):
        return {}
    return pack["entries"]


def _hash_files(root: Path, old: dict[str, Any], old_taken: Any, read: bool,
                scanned: Scan | None = None) -> Files | None:
    """Every file's size, time and content hash, reusing settled hashes of ``old``.

    None when ``read`` is False and some file would have to be read.
    """
    taken = time.time_ns()
    stats: dict[str, list[Any]] = {}
    trusted_before = old_taken - _SETTLED_NS if isinstance(old_taken, int) else -1
    base = os.fspath(root)
    for path, size_time in scan(root) if scanned is None else scanned:
        previous = old.get(path)
        if isinstance(previous, list) and len(previous) == 3 and previous[:2] == size_time \
                and size_time[1] < trusted_before and isinstance(previous[2], str):
            stats[path] = previous
            continue
        if not read:
            return None
        try:
            with open(os.path.join(base, path), "rb") as stream:
                content = sha256(stream.read()).hexdigest()
        except OSError:
            content = "unreadable"
        stats[path] = [*size_time, content]
    return Files(stats, taken)


def _digest(parts: list[Any]) -> str:
    return sha256(json.dumps(parts, separators=(",", ":")).encode()).hexdigest()


def _settings_parts(settings: Settings) -> list[Any]:
    ignores = [[str(base), glob, sorted(codes)] for base, glob, codes in settings.path_ignores]
    return [list(settings.codes), sorted((c, s.value) for c, s in settings.severities.items()),
            ignores, settings.rosdistro, settings.python and list(settings.python)]


def _workspace_key(workspace: Mapping[Path, WorkspacePackage]) -> list[Any]:
    """Every entry of the index, whole: a sibling's message fields and setup files are read
    by the rules too (PYC019, LCH001)."""
    return [[str(folder), *index_record(p)] for folder, p in sorted(workspace.items())]


def _code_fingerprint() -> list[Any]:
    """pkgtool's version, its files' sizes and times, Python's version, installed distributions.

    An edited rule or table (an editable install) or an upgraded dependency (pyflakes, lxml)
    changes the key, so results of other code are never reused.
    """
    import pkgtool

    files = code_files(Path(pkgtool.__file__).parent)
    distributions = sorted(name for entry in site_folders() for name in os.listdir(entry)
                           if name.endswith(".dist-info"))
    return [pkgtool.__version__, sys.version, files, distributions]
