"""Read package files defensively: size cap, binary and encoding checks, never an exception."""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path

from pkgtool.model.span import ParseProblem, Span

MAX_FILE_BYTES = 2 * 1024 * 1024
"""Files larger than this are not parsed (a ``too-large`` problem instead)."""

SKIPPED_DIRS = frozenset({"__pycache__", "node_modules"})
"""Directory names never descended into inside a package (hidden folders are skipped too)."""

BUILD_OUTPUT_DIRS = frozenset({"build", "install", "log"})
"""colcon's output folders: skipped at the package root when they hold no Python package."""


def _skipped(folder: str, name: str, at_root: bool) -> bool:
    """True for a folder (``name`` in ``folder``) whose files are not the package's."""
    if name.startswith(".") or name in SKIPPED_DIRS or name.endswith(".egg-info"):
        return True
    if os.path.isfile(os.path.join(folder, "pyvenv.cfg")) or \
            os.path.isfile(os.path.join(folder, "package.xml")):
        return True  # a virtual environment, or a nested package of its own
    return (at_root and name in BUILD_OUTPUT_DIRS
            and not os.path.isfile(os.path.join(folder, "__init__.py")))


@dataclass(frozen=True, slots=True)
class TextFile:
    """A file's decoded text."""

    path: str
    text: str


def read_text(root: Path, relpath: str, *, allow_empty: bool = True) -> TextFile | ParseProblem:
    """Read ``root/relpath`` as UTF-8 text, or describe why it cannot be read."""
    span = Span(relpath, 1, 1)
    file = root / relpath
    try:
        size = file.stat().st_size
        if size > MAX_FILE_BYTES:
            return ParseProblem("too-large", span,
                                f"{size} bytes, more than the {MAX_FILE_BYTES} read")
        data = file.read_bytes()
    except OSError as error:
        return ParseProblem("unreadable", Span(relpath), error.strerror or str(error))
    if b"\0" in data:
        return ParseProblem("binary", span, "the file contains NUL bytes")
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as error:
        line = data[: error.start].count(b"\n") + 1
        return ParseProblem("not-utf8", Span(relpath, line, 1), f"byte {error.start} is not UTF-8")
    if not allow_empty and not text.strip():
        return ParseProblem("empty", span, "the file is empty")
    return TextFile(relpath, text.removeprefix("\ufeff"))


def list_files(root: Path) -> tuple[str, ...]:
    """Every regular file under ``root`` as sorted POSIX paths, skipping tool and build folders.

    Nested packages (a sub-folder holding its own package.xml) and virtual environments are not
    part of this package.
    """
    found: list[str] = []
    stack = [(os.fspath(root), "")]
    while stack:
        folder, prefix = stack.pop()
        try:
            with os.scandir(folder) as listing:
                entries = list(listing)
        except OSError:
            continue
        for entry in entries:  # is_dir/is_file follow symbolic links; broken ones are neither
            try:
                if entry.is_dir():
                    if not entry.is_symlink() and not _skipped(entry.path, entry.name,
                                                               not prefix):
                        stack.append((entry.path, f"{prefix}{entry.name}/"))
                elif entry.is_file():
                    found.append(prefix + entry.name)
            except OSError:
                continue
    return tuple(sorted(found))
