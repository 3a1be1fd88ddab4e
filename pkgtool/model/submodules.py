"""What the repository around a package says about files the package does not hold.

Git submodules that are not checked out: a clone made without ``--recurse-submodules``
leaves each submodule an empty folder; files the package names inside one are then missing
here, not in the package. They are read from the ``.gitmodules`` of the repository holding
the package (the nearest one above it, below the folder holding ``.git``).

Ignored files: the ``.gitignore`` files of the package and of the folders above it, up to
the one holding ``.git`` (a file the user makes, a calibration, a map, a downloaded model, is
left out of git on purpose), each pattern matched the way git does against the path below the
file's folder: a pattern without a ``/`` (but a trailing one) against every part of it, one
with a ``/`` against its leading parts, a trailing ``/`` matching folders only.
"""

from __future__ import annotations

import os
import re
from fnmatch import fnmatchcase
from functools import lru_cache
from pathlib import Path

from pkgtool.model.files import read_bytes
from pkgtool.records import record
from pkgtool.lazy_regex import lazy_pattern

_PATH = lazy_pattern(rb"^\s*path\s*=\s*(.+?)\s*$", re.M)


def unfetched_submodules(root: Path, files: tuple[str, ...]) -> frozenset[str]:
    """Package-relative folders of the submodules inside ``root`` holding none of ``files``."""
    folder = os.path.abspath(root)
    declared = _declared(folder)
    if declared is None:
        return frozenset()
    top, paths = declared
    found = set()
    for path in paths:
        full = os.path.normpath(os.path.join(top, path))
        if not full.startswith(folder + os.sep):
            continue
        inside = full[len(folder) + 1:].replace(os.sep, "/")
        if not any(f.startswith(inside + "/") for f in files):
            found.add(inside)
    return frozenset(found)


def unfetched_names(root: Path) -> frozenset[str]:
    """The folder names of the repository's submodules that are not checked out (an empty or
    missing folder): a package of the workspace each may hold once fetched, named like it."""
    declared = _declared(os.path.abspath(root))
    if declared is None:
        return frozenset()
    top, paths = declared
    return frozenset(os.path.basename(os.path.normpath(path)) for path in paths
                     if not _has_entries(os.path.join(top, path)))


def _has_entries(folder: str) -> bool:
    try:
        with os.scandir(folder) as entries:
            return any(True for _ in entries)
    except OSError:
        return False


@lru_cache(maxsize=256)
def _declared(folder: str) -> tuple[str, tuple[str, ...]] | None:
    """The repository folder holding ``folder`` and the submodule paths its ``.gitmodules``
    lists; None when there is none (up to the folder holding ``.git``)."""
    listing = os.path.join(folder, ".gitmodules")
    if os.path.isfile(listing):
        try:
            data = read_bytes(listing)
        except OSError:
            return None
        if isinstance(data, int):
            return None
        return folder, tuple(m.decode("utf-8", "replace") for m in _PATH.findall(data))
    parent = os.path.dirname(folder)
    if parent == folder or os.path.exists(os.path.join(folder, ".git")):
        return None
    return _declared(parent)


def under(path: str, folders: frozenset[str]) -> bool:
    """True when the package-relative ``path`` is one of ``folders`` or inside one."""
    return any(path == f or path.startswith(f + "/") for f in folders)


@record
class GitIgnore:
    """A pattern of a ``.gitignore`` file: ``folder`` is where a file of the package holds
    it (package-relative, ``""`` for the package's root or a folder above), ``prefix`` the
    package's path below the folder above that holds it (``""`` for the package's own)."""

    folder: str
    prefix: str
    pattern: str


def ignores_above(root: Path) -> tuple[GitIgnore, ...]:
    """The patterns of the ``.gitignore`` files in the folders above ``root``, up to the one
    holding ``.git`` (all the way up when there is none)."""
    folder = os.path.abspath(root)
    return _ignores(os.path.dirname(folder), os.path.basename(folder) + "/")


@lru_cache(maxsize=256)
def _ignores(folder: str, prefix: str) -> tuple[GitIgnore, ...]:
    found: tuple[GitIgnore, ...] = ()
    listing = os.path.join(folder, ".gitignore")
    if os.path.isfile(listing):
        try:
            data = read_bytes(listing)
        except OSError:
            data = b""
        if isinstance(data, bytes):
            found = tuple(GitIgnore("", prefix, pattern)
                          for pattern in gitignore_patterns(data.decode("utf-8", "replace")))
    parent = os.path.dirname(folder)
    if parent == folder or os.path.exists(os.path.join(folder, ".git")):
        return found
    return found + _ignores(parent, os.path.basename(folder) + "/" + prefix)


def gitignore_patterns(text: str) -> tuple[str, ...]:
    """The patterns of a ``.gitignore`` file: its lines but blanks, comments and negations."""
    return tuple(line.strip() for line in text.splitlines()
                 if line.strip() and not line.lstrip().startswith(("#", "!")))


def ignored(path: str, ignores: tuple[GitIgnore, ...]) -> bool:
    """True when git ignores the file at ``path`` (package-relative) by one of ``ignores``:
    ``ost.yaml``, ``*.pgm``, ``maps/``, ``*/`` in ``models/.gitignore`` for
    ``models/yolo/best.onnx``."""
    for ignore in ignores:
        if ignore.folder and not path.startswith(ignore.folder + "/"):
            continue
        below = ignore.prefix + (path[len(ignore.folder) + 1:] if ignore.folder else path)
        if _matches(below, ignore.pattern):
            return True
    return False


def _matches(path: str, pattern: str) -> bool:
    """True when the ``.gitignore`` ``pattern`` matches ``path`` (below the file's folder) or
    one of the folders it lies in."""
    folders_only = pattern.endswith("/")
    pattern = pattern.rstrip("/")
    if pattern.startswith("**/"):
        pattern = pattern[3:]
    parts = path.split("/")
    if "/" in pattern:  # anchored at the file's folder: match the leading parts
        leading = ("/".join(parts[:count]) for count in range(1, len(parts) + 1))
        return any(fnmatchcase(part, pattern.lstrip("/")) and (count < len(parts) or
                                                               not folders_only)
                   for count, part in enumerate(leading, 1))
    return any(fnmatchcase(part, pattern) and (count < len(parts) or not folders_only)
               for count, part in enumerate(parts, 1))
