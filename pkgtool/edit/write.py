"""All-or-nothing atomic writes inside a package folder.

Each new content goes to a temporary file beside its target (same folder, so the rename is
atomic), with the target's permission bits and owner. Only when every temporary file is ready
are they renamed into place; if a rename fails, the targets replaced so far get their original
content back (kept as hard links until the end) and new files are removed again. A path whose
real location lies outside the package (through a symlink) is refused before anything is
written; a symlink inside the package is written through, the link itself kept.
"""

from __future__ import annotations

import contextlib
import os
import shutil
import tempfile
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from pkgtool.edit.core import EditError
from pkgtool.records import record


def inside(root: Path, relpath: str) -> Path:
    """The real path ``root/relpath`` writes to; EditError when it leaves the package."""
    real_root = root.resolve()
    target = (root / relpath).resolve()
    if target != real_root and real_root not in target.parents:
        raise EditError(f"`{relpath}` leads outside the package (through a symlink) to "
                        f"`{target}`: pkgtool does not write there. Edit it by hand.")
    if target.is_dir():
        raise EditError(f"`{relpath}` is a folder where pkgtool would write a file: move it.")
    return target


@record
class Write:
    """New ``data`` for ``relpath``; ``create`` when the file must not exist yet."""

    relpath: str
    data: bytes
    create: bool = False


@dataclass
class _Staged:
    write: Write
    target: Path
    temporary: Path
    backup: Path | None = None
    done: bool = False


def write_all(root: Path, writes: Sequence[Write]) -> None:
    """Write every file or none; OSError or EditError leaves the package as it was."""
    staged: list[_Staged] = []
    made: list[Path] = []
    try:
        for write in writes:
            target = inside(root, write.relpath)
            made += _make_parents(root.resolve(), target.parent)
            staged.append(_Staged(write, target, _temporary(target, write)))
        for item in staged:
            _commit(item)
    except BaseException:
        for item in reversed(staged):
            _undo(item)
        _clean(staged)
        for folder in reversed(made):
            with contextlib.suppress(OSError):
                folder.rmdir()
        raise
    _clean(staged)


def _clean(staged: list[_Staged]) -> None:
    """Remove the temporary files and backups that are left."""
    for item in staged:
        for leftover in (item.temporary, item.backup):
            if leftover is not None:
                with contextlib.suppress(OSError):
                    leftover.unlink()


def _make_parents(root: Path, folder: Path) -> list[Path]:
    missing = [p for p in (folder, *folder.parents) if not p.exists() and root in p.parents]
    for path in reversed(missing):
        path.mkdir()
    return list(reversed(missing))


def _temporary(target: Path, write: Write) -> Path:
    """A temporary file beside ``target`` holding the new data, mode and owner set."""
    handle, name = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".pkgtool",
                                    dir=target.parent)
    temporary = Path(name)
    try:
        with os.fdopen(handle, "wb") as out:
            out.write(write.data)
            out.flush()
            os.fsync(out.fileno())
        if write.create:
            if target.exists() or target.is_symlink():
                raise EditError(f"`{write.relpath}` appeared while pkgtool was writing; "
                                "nothing was changed. Run the command again.")
            umask = os.umask(0)
            os.umask(umask)
            os.chmod(temporary, 0o666 & ~umask)
        else:
            _copy_owner_and_mode(target, temporary, write.relpath)
    except BaseException:
        temporary.unlink(missing_ok=True)
        raise
    return temporary


def _copy_owner_and_mode(target: Path, temporary: Path, relpath: str) -> None:
    status = target.stat()
    os.chmod(temporary, status.st_mode & 0o7777)
    mine = temporary.stat()
    if (mine.st_uid, mine.st_gid) != (status.st_uid, status.st_gid):
        try:
            os.chown(temporary, status.st_uid, status.st_gid)
        except PermissionError:
            raise EditError(f"`{relpath}` belongs to another user or group, which a rewrite "
                            "could not keep: nothing was changed. Run as its owner.") from None


def _commit(item: _Staged) -> None:
    if item.write.create:
        try:
            os.link(item.temporary, item.target)  # fails rather than replace a file that appeared
        except FileExistsError:
            raise
        except OSError:  # no hard links here: claim the name, then move the content in
            os.close(os.open(item.target, os.O_WRONLY | os.O_CREAT | os.O_EXCL))
            item.done = True
            os.replace(item.temporary, item.target)
    else:
        item.backup = item.temporary.with_name(item.temporary.name + ".orig")
        try:
            os.link(item.target, item.backup)
        except OSError:
            shutil.copy2(item.target, item.backup)
        os.replace(item.temporary, item.target)
    item.done = True


def _undo(item: _Staged) -> None:
    if not item.done:
        return
    with contextlib.suppress(OSError):
        if item.write.create:
            item.target.unlink()
        elif item.backup is not None:
            os.replace(item.backup, item.target)
            item.backup = None
