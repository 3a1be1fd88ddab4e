"""File operations on trees that untrusted code made: no link followed, no recursion, no hang.

Every path is opened one component at a time relative to a folder descriptor with
``O_NOFOLLOW`` (so a symbolic link anywhere on the way is refused, whatever its length or
chain: ``os.path.realpath`` is never trusted), files with ``O_NONBLOCK`` and checked with
``fstat`` to be regular (a FIFO cannot block the reader), and sizes are capped. Trees are
walked and removed with explicit stacks, so any depth works.
"""

from __future__ import annotations

import errno
import os
import stat
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path, PurePosixPath
from typing import BinaryIO

from pkgtool.records import record

_DIR = os.O_RDONLY | os.O_DIRECTORY | os.O_NOFOLLOW | os.O_CLOEXEC
_FILE = os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK | os.O_NOCTTY | os.O_CLOEXEC
MB = 1024 * 1024


class UnsafeFile(Exception):
    """A file that is not a plain regular file inside its folder, or is too large."""


def read_regular(path: Path, *, within: Path, max_bytes: int) -> bytes:
    """The bytes of ``path``, a regular file below the trusted folder ``within``.

    FileNotFoundError when it is missing; UnsafeFile when a component is a link, the file is
    not regular (FIFO, device, folder) or holds more than ``max_bytes``.
    """
    try:
        parts = path.relative_to(within).parts
    except ValueError:
        raise UnsafeFile(f"{path} is outside {within}") from None
    if not parts:
        raise UnsafeFile(f"{path} is a folder")
    folder = os.open(within, _DIR)
    try:
        for part in parts[:-1]:
            folder = _descend(folder, part)
        with open_regular(folder, parts[-1]) as handle:
            data = handle.read(max_bytes + 1)
    finally:
        os.close(folder)
    if len(data) > max_bytes:
        raise UnsafeFile(f"{path.name} is larger than {max_bytes} bytes")
    return data


def _descend(folder: int, name: str) -> int:
    """Open sub-folder ``name`` of ``folder`` and close ``folder`` (left open on an error,
    for the caller to close); a link is refused."""
    try:
        child = os.open(name, _DIR, dir_fd=folder)
    except OSError as error:
        if error.errno in (errno.ELOOP, errno.ENOTDIR):
            raise UnsafeFile(f"`{name}` is a link or not a folder") from None
        raise
    os.close(folder)
    return child


def open_regular(folder: int, name: str) -> BinaryIO:
    """Open ``name`` in ``folder`` for reading, only as a regular file (no link, no FIFO)."""
    try:
        fd = os.open(name, _FILE, dir_fd=folder)
    except OSError as error:
        if error.errno == errno.ELOOP:
            raise UnsafeFile(f"`{name}` is a symbolic link") from None
        raise
    if not stat.S_ISREG(os.fstat(fd).st_mode):
        os.close(fd)
        raise UnsafeFile(f"`{name}` is not a regular file")
    os.set_blocking(fd, True)
    return os.fdopen(fd, "rb")


def lexical_target(base: Sequence[str], target: str) -> tuple[str, ...] | None:
    """The path parts (from the root) that ``target``, read in folder ``base``, names.

    Computed on the text alone (a symbolic link's target is read in the link's folder, a hard
    link's at the root); None for an absolute target or one climbing out of the root. The
    caller then checks that every component of the result is a plain folder or file.
    """
    if not target or target.startswith("/") or "\0" in target:
        return None
    parts = list(base)
    for part in PurePosixPath(target).parts:
        if part == "..":
            if not parts:
                return None
            parts.pop()
        elif part != ".":
            parts.append(part)
    return tuple(parts) or None


@record
class Entry:
    """A walked entry: its path parts below the root and its lstat; ``open`` and ``readlink``
    work on it (relative to its folder's descriptor) until the walk moves on."""

    parts: tuple[str, ...]
    info: os.stat_result
    folder: int

    def open(self) -> BinaryIO:
        """The entry's content, when it is a regular file (else UnsafeFile)."""
        return open_regular(self.folder, self.parts[-1])

    def readlink(self) -> str:
        """The entry's link target, when it is a symbolic link."""
        return os.readlink(self.parts[-1], dir_fd=self.folder)


Keep = Callable[[tuple[str, ...], frozenset[str], frozenset[str]], bool]
"""Whether to walk into a folder: its parts, the names beside it, the names in it."""


def walk_tree(root: Path, *, max_depth: int, keep: Keep | None = None) -> Iterator[Entry]:
    """Every entry below ``root`` (sorted per folder, links not followed), depth first.

    Folders for which ``keep`` says False are left out with everything in them. A folder
    deeper than ``max_depth`` raises UnsafeFile; so does a ``root`` that is a link.
    """
    try:
        top = os.open(root, _DIR)
    except OSError as error:
        if error.errno in (errno.ELOOP, errno.ENOTDIR):
            raise UnsafeFile(f"`{root.name}` is a symbolic link or not a folder") from None
        raise
    listed = sorted(os.listdir(top))
    stack = [((), top, listed, frozenset(listed))]
    try:
        while stack:
            parts, folder, names, beside = stack[-1]
            if not names:
                os.close(stack.pop()[1])
                continue
            name = names.pop(0)
            try:
                info = os.lstat(name, dir_fd=folder)
            except FileNotFoundError:
                continue
            if not stat.S_ISDIR(info.st_mode):
                yield Entry((*parts, name), info, folder)
                continue
            if len(parts) + 1 > max_depth:
                raise UnsafeFile(f"folders are nested more than {max_depth} deep")
            child = os.open(name, _DIR, dir_fd=folder)
            inside = sorted(os.listdir(child))
            if keep is not None and not keep((*parts, name), beside, frozenset(inside)):
                os.close(child)
                continue
            yield Entry((*parts, name), info, folder)
            stack.append(((*parts, name), child, inside, frozenset(inside)))
    finally:
        for _, folder, _, _ in stack:
            os.close(folder)


def open_path(root: Path, parts: Sequence[str]) -> BinaryIO:
    """Open the regular file ``root/parts``, every folder on the way a real folder."""
    folder = os.open(root, _DIR)
    try:
        for part in parts[:-1]:
            folder = _descend(folder, part)
        return open_regular(folder, parts[-1])
    finally:
        os.close(folder)


def remove_tree(path: Path) -> None:
    """Delete ``path`` and everything below it, at any depth, following no link.

    Each sub-folder is moved up to ``path`` itself before it is emptied, so neither the
    stack nor a path ever grows with the depth (a 3000-deep tree is no problem).
    """
    try:
        top = os.open(path, _DIR)
    except FileNotFoundError:
        return
    except OSError as error:
        if error.errno not in (errno.ELOOP, errno.ENOTDIR):
            raise
        os.unlink(path)
        return
    try:
        _empty(top)
    finally:
        os.close(top)
    os.rmdir(path)


def _empty(top: int) -> None:
    pending: list[str | None] = [None]
    moved = 0
    while pending:
        name = pending.pop()
        folder = top if name is None else os.open(name, _DIR, dir_fd=top)
        try:
            if os.geteuid() != 0:
                os.fchmod(folder, 0o700)
            for entry in list(os.scandir(folder)):
                if not entry.is_dir(follow_symlinks=False):
                    os.unlink(entry.name, dir_fd=folder)
                elif name is None:
                    pending.append(entry.name)
                else:
                    while _exists(top, f".pkgtool-rm-{moved}"):
                        moved += 1
                    os.rename(entry.name, f".pkgtool-rm-{moved}", src_dir_fd=folder,
                              dst_dir_fd=top)
                    pending.append(f".pkgtool-rm-{moved}")
        finally:
            if name is not None:
                os.close(folder)
        if name is not None:
            os.rmdir(name, dir_fd=top)


def _exists(folder: int, name: str) -> bool:
    try:
        os.lstat(name, dir_fd=folder)
    except FileNotFoundError:
        return False
    return True


class TreeWriter:
    """Creates folders and new files below an existing empty folder, never through a link.

    Every file is created with ``O_EXCL``: nothing already there is overwritten.
    """

    def __init__(self, root: Path) -> None:
        self.root = root

    def folder(self, parts: Sequence[str]) -> int:
        """Open (creating as needed) the folder ``parts``; the caller closes the descriptor."""
        folder = os.open(self.root, _DIR)
        try:
            for part in parts:
                try:
                    os.mkdir(part, 0o755, dir_fd=folder)
                except FileExistsError:
                    pass
                folder = _descend(folder, part)
        except BaseException:
            os.close(folder)
            raise
        return folder

    def file(self, parts: Sequence[str], chunks: Iterator[bytes], *, executable: bool) -> int:
        """Write a new file from ``chunks``; returns its size."""
        folder = self.folder(parts[:-1])
        try:
            fd = os.open(parts[-1], os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW
                         | os.O_CLOEXEC, 0o755 if executable else 0o644, dir_fd=folder)
        finally:
            os.close(folder)
        os.fchmod(fd, 0o755 if executable else 0o644)
        size = 0
        with os.fdopen(fd, "wb") as sink:
            for chunk in chunks:
                size += len(chunk)
                sink.write(chunk)
        return size
