"""Read package files defensively: size cap, binary and encoding checks, never an exception."""

from __future__ import annotations

import errno
import os
import stat
from functools import cached_property
from pathlib import Path
from typing import Callable

from pkgtool.model.span import ParseProblem, Span
from pkgtool.records import record
from pkgtool.workspace import SKIP_MARKERS, listing

MAX_FILE_BYTES = 2 * 1024 * 1024
"""Files larger than this are not parsed (a ``too-large`` problem instead)."""

SKIPPED_DIRS = frozenset({"__pycache__", "node_modules"})
"""Directory names never descended into inside a package (hidden folders are skipped too)."""

APPLE_DOUBLE = "._"
"""How the names of the metadata files macOS writes beside each file it copies to a foreign
disk begin (``._talker.py``, binary): no file of the package, never listed."""

DESCRIPTION_SUFFIXES = (".urdf", ".xacro", ".sdf", ".srdf", ".world", ".rviz")
"""Robot description, world and RViz files: a package installs them as written (code never
makes them at run time, as it may a map), and they name other packages by ``$(find ...)`` or
``package://`` URIs."""

BUILD_OUTPUT_DIRS = frozenset({"build", "install", "log"})
"""colcon's output folders: skipped at the package root when they hold no Python package."""


def _skipped_name(name: str) -> bool:
    """True for a folder never descended into, whatever it holds."""
    return name.startswith(".") or name in SKIPPED_DIRS or name.endswith(".egg-info")


_INSTALLED_PACKAGES = frozenset({"site-packages", "dist-packages"})
"""Folders where pip and apt install other projects' code (a committed virtual environment)."""
_OLD_VIRTUALENV = frozenset({"orig-prefix.txt", "no-global-site-packages.txt"})
"""Files that virtualenv before 20.0 (every Python 2 one) writes into ``lib/pythonX.Y``,
instead of the ``pyvenv.cfg`` of newer environments."""


_NESTED_MARKERS = SKIP_MARKERS | {"package.xml"}
"""The files of a nested package that are listed: its package.xml, and whether colcon skips it."""


def _not_the_packages(name: str, files: set[str], at_root: bool) -> bool:
    """True for a folder ``name`` holding ``files`` whose files are not the package's: a
    virtual environment (or the ``lib/pythonX.Y`` or ``site-packages`` folder of one), or a
    package of its own nested in this one, unless it is a Python
    package of this one too (an ``__init__.py``: colcon never looks for packages inside a
    package, and setuptools installs the folder with this package's code)."""
    if "pyvenv.cfg" in files or "package.xml" in files and "__init__.py" not in files or \
            name in _INSTALLED_PACKAGES or files & _OLD_VIRTUALENV:
        return True
    return at_root and name in BUILD_OUTPUT_DIRS and "__init__.py" not in files


def _setuptools_output(prefix: str, name: str, build_folders: set[str]) -> bool:
    """True for what setuptools builds into a project's ``build/`` folder below the package
    root (``vendor/lib/build/lib/``, ``build/bdist.linux-x86_64/``): copies of another
    project's code, never the package's sources. ``build_folders``: the folders named
    ``build`` met so far that are no Python package (no ``__init__.py``)."""
    return prefix in build_folders and (name == "lib" or name.startswith(("lib.", "bdist.")))


@record
class TextFile:
    """A file's decoded text."""

    path: str
    text: str


def read_text(root: Path, relpath: str, *, allow_empty: bool = True) -> TextFile | ParseProblem:
    """Read ``root/relpath`` as UTF-8 text, or describe why it cannot be read."""
    span = Span(relpath, 1, 1)
    try:
        data = read_bytes(os.path.join(root, relpath))
    except OSError as error:
        return ParseProblem("unreadable", Span(relpath), error.strerror or str(error))
    if isinstance(data, int):
        return ParseProblem("too-large", span,
                            f"{data} bytes, more than the {MAX_FILE_BYTES} read")
    if b"\0" in data:
        return ParseProblem("binary", span, "the file contains NUL bytes")
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as error:
        accepted = python_source(data) if relpath.endswith(".py") else None
        if accepted is None:
            line = data[: error.start].count(b"\n") + 1
            return ParseProblem("not-utf8", Span(relpath, line, 1),
                                f"byte {error.start} is not UTF-8")
        text = accepted
    if not allow_empty and not text.strip():
        return ParseProblem("empty", span, "the file is empty")
    return TextFile(relpath, text.removeprefix("\ufeff"))


def python_source(data: bytes) -> str | None:
    """The text of Python source that is not UTF-8 yet Python compiles: bytes of another
    encoding in comments only (which CPython never decodes), or a file declaring its encoding
    (``# -*- coding: latin-1 -*-``); None when Python rejects it too. Compiled to a syntax
    tree only, never run."""
    import ast
    import io
    import tokenize

    try:
        encoding, _ = tokenize.detect_encoding(io.BytesIO(data).readline)
        compile(data, "<source>", "exec", ast.PyCF_ONLY_AST, dont_inherit=True)
        return data.decode(encoding, errors="replace")
    except (SyntaxError, ValueError, LookupError):
        return None


_READ_FLAGS = os.O_RDONLY | getattr(os, "O_BINARY", 0) | getattr(os, "O_NONBLOCK", 0)
"""O_BINARY: Windows translates no newline; O_NONBLOCK: opening a FIFO does not wait for a
writer (regular files ignore it)."""


def read_bytes(path: str) -> bytes | int:
    """The file's bytes, or its size when that is over :data:`MAX_FILE_BYTES`.

    Read through a file descriptor: a Python file object costs more than reading a small file.
    Only regular files are read (a FIFO, a device such as ``/dev/zero`` behind a link, raise
    OSError), and never more than the limit.
    """
    descriptor = os.open(path, _READ_FLAGS)
    try:
        status = os.fstat(descriptor)
        if not stat.S_ISREG(status.st_mode):
            raise OSError(errno.EINVAL, "not a regular file", path)
        if status.st_size > MAX_FILE_BYTES:
            return status.st_size
        data = os.read(descriptor, status.st_size + 1)  # one read when the size is right
        while len(data) > status.st_size:  # the file grew meanwhile: read on to its end
            more = os.read(descriptor, 1 << 16)
            if not more:
                break
            data += more
            if len(data) > MAX_FILE_BYTES:
                return len(data)
        return data
    finally:
        os.close(descriptor)


def list_files(root: Path, depth: Callable[[str], int | None] | None = None
               ) -> tuple[str, ...]:
    """Every regular file under ``root`` as sorted POSIX paths, skipping tool and build folders.

    Nested packages (a sub-folder holding its own package.xml) and virtual environments are not
    part of this package: of a nested package only its package.xml (and a ``COLCON_IGNORE``,
    ``AMENT_IGNORE`` or ``CATKIN_IGNORE`` beside it) is listed, which marks the folder
    (:func:`~pkgtool.model.launch.nested_packages`; CMake may install it whole).
    ``depth(name)``, when given, says how many folder levels to read below the top-level
    folder ``name`` (0: not read; None: all): the same files as without it, less those
    deeper than that.
    """
    return tuple(sorted(path for path, _ in _walk(root, depth)))


Scan = list[tuple[str, list[int]]]
"""A package's files (sorted POSIX paths) with their ``[size, mtime_ns]``."""


def scan(root: Path) -> Scan:
    """Every file of :func:`list_files` (sorted) with its ``[size, mtime_ns]``, in one walk.

    A file that vanishes or cannot be examined meanwhile gets ``[-1, -1]``.
    """
    return sorted((path, _size_time(entry)) for path, entry in _walk(root))


def _walk(root: Path, depth: Callable[[str], int | None] | None = None
          ) -> list[tuple[str, os.DirEntry[str]]]:
    """The package's files (POSIX paths relative to ``root``), each folder listed once; with
    ``depth``, only as deep as it says (see :func:`list_files`)."""
    found: list[tuple[str, os.DirEntry[str]]] = []
    stack: list[tuple[str, list[os.DirEntry[str]], int | None]] = [
        ("", listing(os.fspath(root)), None)]
    linked = _LinkedFolders(os.fspath(root))
    build_folders: set[str] = set()  # below the root, holding no __init__.py
    while stack:
        prefix, entries, left = stack.pop()
        for entry in entries:  # is_dir/is_file follow symbolic links; broken ones are neither
            try:
                if entry.is_dir():
                    if _skipped_name(entry.name) or entry.is_symlink() and \
                            not linked.follow(entry.path):
                        continue
                    below = depth(entry.name) if depth and not prefix else left
                    if below is not None and below < 1:
                        continue
                    inside = listing(entry.path)
                    files = {e.name for e in inside if e.is_file()}
                    if not _not_the_packages(entry.name, files, not prefix) and \
                            not _setuptools_output(prefix, entry.name, build_folders):
                        deeper = None if below is None else below - 1
                        stack.append((f"{prefix}{entry.name}/", inside, deeper))
                        if prefix and entry.name == "build" and "__init__.py" not in files:
                            build_folders.add(f"{prefix}{entry.name}/")
                    elif "package.xml" in files and "pyvenv.cfg" not in files:
                        found.extend((f"{prefix}{entry.name}/{e.name}", e) for e in inside
                                     if e.name in _NESTED_MARKERS)  # marks the nested package
                elif entry.is_file() and not entry.name.startswith(APPLE_DOUBLE):
                    found.append((prefix + entry.name, entry))
            except OSError:
                continue
    return found


class _LinkedFolders:
    """Which symbolic links to folders a walk of a package follows, as setuptools' does
    (``find_packages`` installs a package folder linked from another): each target once, and
    only inside the repository holding the package (the nearest folder up with ``.git``, else
    the package's parent folder), never a folder around the package (a loop)."""

    def __init__(self, root: str) -> None:
        self.given = root
        self.seen: set[str] = set()

    @cached_property
    def place(self) -> tuple[str, str]:
        """The package's real folder and the folder links must stay inside, worked out at the
        first link (most packages have none)."""
        root = top = os.path.realpath(self.given)
        while not os.path.exists(os.path.join(top, ".git")) and os.path.dirname(top) != top:
            top = os.path.dirname(top)
        return root, top if os.path.exists(os.path.join(top, ".git")) else os.path.dirname(root)

    def follow(self, path: str) -> bool:
        root, boundary = self.place
        target = os.path.realpath(path)
        inside = target.startswith(boundary + os.sep)
        around = root == target or root.startswith(target + os.sep)
        if not inside or around or target in self.seen:
            return False
        self.seen.add(target)
        return True


def _size_time(entry: os.DirEntry[str]) -> list[int]:
    try:
        stat = entry.stat()
    except OSError:
        return [-1, -1]
    return [stat.st_size, stat.st_mtime_ns]
