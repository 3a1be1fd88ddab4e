"""The package's file list seen as a directory tree: globbing and package finding without I/O.

Paths are package-relative POSIX strings; ``""`` is the package root (setup.py's directory,
where colcon runs it).
"""

from __future__ import annotations

import posixpath
import re
from collections.abc import Iterable, Iterator
from fnmatch import fnmatchcase

_MAGIC = re.compile(r"[*?[]")

FINDER_EXCLUDES = ("ez_setup", "*__pycache__")
"""Patterns setuptools' package finders always exclude."""


def normalize(path: str) -> str | None:
    """``path`` as package-relative POSIX (``""`` for the root); None if absolute or outside."""
    if not path or path.startswith("/"):
        return None if path.startswith("/") else ""
    normal = posixpath.normpath(path)
    if normal == ".":
        return ""
    if normal == ".." or normal.startswith("../"):
        return None
    return normal


class Tree:
    """Files and the folders that hold them."""

    def __init__(self, files: Iterable[str]) -> None:
        self.files = frozenset(files)
        self.children: dict[str, set[str]] = {"": set()}
        for file in self.files:
            parts = file.split("/")
            for depth in range(len(parts)):
                parent = "/".join(parts[:depth])
                self.children.setdefault(parent, set()).add(parts[depth])

    def is_file(self, path: str) -> bool:
        """True when ``path`` names a file of the package."""
        return path in self.files

    def is_dir(self, path: str) -> bool:
        """True when ``path`` names a folder holding files (``""`` is the root)."""
        return path in self.children

    def listdir(self, folder: str) -> list[str]:
        """Sorted entry names of ``folder``."""
        return sorted(self.children.get(folder, ()))

    def subdirs(self, folder: str) -> list[str]:
        """Sorted names of the sub-folders of ``folder``."""
        return [n for n in self.listdir(folder) if self.is_dir(_join(folder, n))]

    def glob(self, pattern: str, *, recursive: bool, hidden: bool = False,
             dirs_only_at_end: bool = False) -> list[str]:
        """Paths matching ``pattern`` like ``glob.glob`` (``hidden``: pathlib's rules)."""
        if not pattern:
            return []
        parts = pattern.split("/")
        trailing = parts[-1] == ""
        if trailing:
            parts = parts[:-1]
        found = sorted(set(self._match("", parts, recursive, hidden)))
        if trailing or (dirs_only_at_end and parts[-1:] == ["**"]):
            return [p for p in found if self.is_dir(p.rstrip("/"))]
        return found

    def _match(self, base: str, parts: list[str], recursive: bool, hidden: bool
               ) -> Iterator[str]:
        if not parts:
            yield base
            return
        head, rest = parts[0], parts[1:]
        if head == "**" and recursive:
            if rest:
                for folder in self._below(base, hidden, dirs=True):
                    yield from self._match(folder, rest, recursive, hidden)
            else:
                yield from ([base + "/"] if base else [])
                yield from (p for p in self._below(base, hidden, dirs=False) if p != base)
            return
        if head in ("", ".") or not _MAGIC.search(head):
            path = _join(base, head) if head not in ("", ".") else base
            if self.is_dir(path) or (not rest and self.is_file(path)):
                yield from self._match(path, rest, recursive, hidden)
            return
        for name in self.listdir(base):
            visible = hidden or not name.startswith(".") or head.startswith(".")
            path = _join(base, name)
            if visible and fnmatchcase(name, head) and (not rest or self.is_dir(path)):
                yield from self._match(path, rest, recursive, hidden)

    def _below(self, base: str, hidden: bool, *, dirs: bool) -> Iterator[str]:
        """``base`` and every folder (and file, unless ``dirs``) below it, hidden ones skipped."""
        yield base
        for name in self.listdir(base):
            path = _join(base, name)
            if not hidden and name.startswith("."):
                continue
            if self.is_dir(path):
                yield from self._below(path, hidden, dirs=dirs)
            elif not dirs:
                yield path

    def find_packages(self, where: str, include: tuple[str, ...], exclude: tuple[str, ...],
                      *, namespace: bool) -> list[str]:
        """setuptools' ``find_packages``/``find_namespace_packages`` over this tree."""
        root = normalize(where)
        if root is None or not self.is_dir(root):
            return []
        excluded = (*FINDER_EXCLUDES, *exclude)
        found: list[str] = []
        stack = [(root, "")]
        while stack:
            folder, prefix = stack.pop()
            for name in self.subdirs(folder):
                path = _join(folder, name)
                package = prefix + name
                if "." in name or not (namespace or self.is_file(path + "/__init__.py")):
                    continue
                if any(fnmatchcase(package, p) for p in include) and \
                        not any(fnmatchcase(package, p) for p in excluded):
                    found.append(package)
                if f"{package}*" not in excluded and f"{package}.*" not in excluded:
                    stack.append((path, package + "."))
        return sorted(found)


def _join(base: str, name: str) -> str:
    return f"{base}/{name}" if base else name
