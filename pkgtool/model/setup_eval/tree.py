"""The package's file list seen as a directory tree: globbing and package finding without I/O.

Paths are package-relative POSIX strings; ``""`` is the package root (setup.py's directory,
where colcon runs it).
"""

from __future__ import annotations

import posixpath
from collections.abc import Iterable, Iterator
from fnmatch import fnmatchcase

from pkgtool.model.setup_eval.bounds import MAX_COST, Budget, TooLarge
from pkgtool.lazy_regex import lazy_pattern

_MAGIC = lazy_pattern(r"[*?[]")

VISIT_COST = 20
"""Budget units per folder entry a glob visits (Python-level work: about 20 characters' worth
of string work each)."""

MAX_GLOB_COST = 2_000_000
"""Budget units one glob may spend (about 100,000 visited entries)."""

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
    """Files and the folders that hold them; globbing charges each visited entry to
    ``budget`` (a nested ``**`` pattern costs its real work, and is refused past the bound)."""

    def __init__(self, files: Iterable[str], budget: Budget | None = None) -> None:
        self.budget = budget or Budget()
        self.stop_at = MAX_COST
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
        names = self.children.get(folder, ())
        self._charge(len(names))
        return sorted(names)

    def subdirs(self, folder: str) -> list[str]:
        """Sorted names of the sub-folders of ``folder``."""
        return [n for n in self.listdir(folder) if self.is_dir(_join(folder, n))]

    def glob(self, pattern: str, *, recursive: bool, hidden: bool = False,
             dirs_only_at_end: bool = False) -> list[str]:
        """Paths matching ``pattern`` like ``glob.glob`` (``hidden``: pathlib's rules)."""
        if not pattern:
            return []
        self.stop_at = self.budget.cost + MAX_GLOB_COST
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
        self._charge(1)
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
        self._charge(1)
        yield base
        for name in self.listdir(base):
            path = _join(base, name)
            if not hidden and name.startswith("."):
                continue
            if self.is_dir(path):
                yield from self._below(path, hidden, dirs=dirs)
            elif not dirs:
                yield path

    def _charge(self, entries: int) -> None:
        """Charge visited entries; one glob may cost MAX_GLOB_COST at most."""
        self.budget.charge(VISIT_COST * entries)
        if self.budget.cost > self.stop_at:
            raise TooLarge("glob")

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


def spelled_as_written(pattern: str, matches: list[str]) -> list[str] | None:
    """``matches`` of ``normalize(pattern)`` spelled as ``glob.glob(pattern)`` returns them.

    glob keeps the literal folders before the first wildcard as written (``./launch/x``) and a
    trailing slash; None when other spellings (``*/./x``, ``*//x``) would need more care.
    """
    parts = pattern.split("/")
    first = next((i for i, part in enumerate(parts) if _MAGIC.search(part)), len(parts))
    rest = parts[first:]
    if any(part in ("", ".", "..") for part in rest[:-1]) or rest[-1:] in (["."], [".."]):
        return None
    trailing = "/" if pattern.endswith("/") else ""
    if not rest:
        return [pattern for _ in matches]
    head = "/".join(parts[:first]).rstrip("/")
    normal = normalize(head) if head else ""
    if normal is None:
        return None
    cut = len(normal) + 1 if normal else 0
    prefix = head + "/" if head else ""
    return [prefix + match[cut:].rstrip("/") + trailing if match != normal + "/" else
            prefix for match in matches]


def _join(base: str, name: str) -> str:
    return f"{base}/{name}" if base else name


class BlindTree(Tree):
    """A package with no files whose globs and package finders are refused (their values
    unresolved): what setup.py computes without looking at its files evaluates as before."""

    def __init__(self, budget: Budget | None = None) -> None:
        super().__init__((), budget)

    def glob(self, pattern: str, *, recursive: bool, hidden: bool = False,
             dirs_only_at_end: bool = False) -> list[str]:
        """Refused (every caller evaluates it under the interpreter's guard)."""
        raise TooLarge("a glob, not read")

    def find_packages(self, where: str, include: tuple[str, ...], exclude: tuple[str, ...],
                      *, namespace: bool) -> list[str]:
        """Refused, like :meth:`glob`."""
        raise TooLarge("a package finder, not read")
