"""What the repository around a package says about files the package does not hold.

Git submodules that are not checked out: a clone made without ``--recurse-submodules``
leaves each submodule an empty folder; files the package names inside one are then missing
here, not in the package. They are read from the ``.gitmodules`` of the repository holding
the package (the nearest one above it, below the folder holding ``.git``).

Ignored files: the ``.gitignore`` files of the folders above the package, up to the one
holding ``.git`` (a file the user makes, a calibration, a map, is left out of git on
purpose); the package's own ``.gitignore`` files are among its files.
"""

from __future__ import annotations

import os
import re
from fnmatch import fnmatch
from functools import lru_cache
from pathlib import Path

from pkgtool.model.files import read_bytes

_PATH = re.compile(rb"^\s*path\s*=\s*(.+?)\s*$", re.M)


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


def ignores_above(root: Path) -> tuple[str, ...]:
    """The patterns of the ``.gitignore`` files in the folders above ``root``, up to the one
    holding ``.git`` (all the way up when there is none)."""
    return _ignores(os.path.dirname(os.path.abspath(root)))


@lru_cache(maxsize=256)
def _ignores(folder: str) -> tuple[str, ...]:
    found: tuple[str, ...] = ()
    listing = os.path.join(folder, ".gitignore")
    if os.path.isfile(listing):
        try:
            data = read_bytes(listing)
        except OSError:
            data = b""
        if isinstance(data, bytes):
            found = gitignore_patterns(data.decode("utf-8", "replace"))
    parent = os.path.dirname(folder)
    if parent == folder or os.path.exists(os.path.join(folder, ".git")):
        return found
    return found + _ignores(parent)


def gitignore_patterns(text: str) -> tuple[str, ...]:
    """The patterns of a ``.gitignore`` file: its lines but blanks, comments and negations."""
    return tuple(line.strip() for line in text.splitlines()
                 if line.strip() and not line.lstrip().startswith(("#", "!")))


def ignored(path: str, patterns: tuple[str, ...]) -> bool:
    """True when a pattern without a folder part matches the file name of ``path`` (a
    package-relative path): ``ost.yaml``, ``*.pgm``."""
    name = path.rpartition("/")[2]
    return any("/" not in pattern.rstrip("/") and fnmatch(name, pattern) for pattern in patterns)
