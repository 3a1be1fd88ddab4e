"""Write a rendered package atomically, never replacing a file that exists, and draw its tree.

A new package is written into a hidden staging folder beside the destination and renamed into
place in one step, so a failure halfway leaves nothing behind. With ``force`` into an existing
folder, only missing files are added (each opened with "x", which fails rather than replace);
if one fails, the files added so far are removed again.
"""

from __future__ import annotations

import contextlib
import os
import secrets
import shutil
from collections.abc import Callable, Mapping
from pathlib import Path

from pkgtool.create import CreateError

Hook = Callable[[str], None]
"""Called with each relative path just before it is written (tests inject failures here)."""


def _stage(files: Mapping[str, str], staging: Path, before_write: Hook | None) -> None:
    for relpath, text in files.items():
        if before_write:
            before_write(relpath)
        path = staging / relpath
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8", newline="\n")


def conflicts(root: Path, files: Mapping[str, str]) -> list[str]:
    """Paths where a file cannot go because a folder is there (or a file where a folder goes)."""
    found = []
    for relpath in files:
        path = root / relpath
        if path.is_dir():
            found.append(relpath)
        parent = path.parent
        while parent != root and parent.parent != parent:
            if parent.exists() and not parent.is_dir():
                found.append(parent.relative_to(root).as_posix())
            parent = parent.parent
    return sorted(set(found))


def enclosing_package(folder: Path) -> Path | None:
    """The package folder (one with a package.xml) that ``folder`` is or is inside, if any."""
    for candidate in (folder.absolute(), *folder.absolute().parents):
        if (candidate / "package.xml").is_file():
            return candidate
    return None


def check_destination(root: Path, files: Mapping[str, str], *,
                      force: bool) -> tuple[list[str], list[str]]:
    """(missing, kept): the paths to write and the existing ones to leave alone.

    ``root`` must not exist unless ``force``. Raises CreateError for a refused destination.
    """
    if root.exists() and not force:
        raise CreateError(f"`{root}` already exists. Choose another name or "
                          "--destination-directory, or add --force to add only missing files.")
    if root.exists() and not root.is_dir():
        raise CreateError(f"`{root}` exists and is not a folder: remove it or choose another "
                          "name.")
    clash = conflicts(root, files) if root.exists() else []
    if clash:
        names = ", ".join(f"`{path}`" for path in clash)
        raise CreateError(f"Cannot add files under `{root}`: {names} is in the way "
                          "(a file where a folder belongs, or the reverse). Move it and retry.")
    missing = sorted(p for p in files if not (root / p).exists())
    return missing, sorted(set(files) - set(missing))


def write_package(root: Path, files: Mapping[str, str], *, force: bool = False,
                  before_write: Hook | None = None) -> tuple[list[str], list[str]]:
    """Write ``files`` under ``root``; return (written, kept) relative paths.

    Raises CreateError for a refused destination, OSError when the disk fails; either way
    nothing of this call is left on disk.
    """
    missing, kept = check_destination(root, files, force=force)
    made = [p for p in root.parents if not p.exists()]  # destination folders to create
    root.parent.mkdir(parents=True, exist_ok=True)
    staging = root.parent / f".{root.name}.pkgtool-{os.getpid()}-{secrets.token_hex(4)}"
    try:
        staging.mkdir()  # unlike mkdtemp, keeps the umask's permissions for the renamed folder
        _stage({p: files[p] for p in missing}, staging, before_write)
        if root.exists():
            _move_missing(staging, root, missing)
        else:
            os.rename(staging, root)
    except BaseException:
        shutil.rmtree(staging, ignore_errors=True)
        for folder in made:  # innermost first; only if still empty
            with contextlib.suppress(OSError):
                folder.rmdir()
        raise
    shutil.rmtree(staging, ignore_errors=True)
    return missing, kept


def _move_missing(staging: Path, root: Path, relpaths: list[str]) -> None:
    """Copy each staged file into ``root``; on any failure undo what this call added."""
    added: list[Path] = []
    made: list[Path] = []
    try:
        for relpath in sorted(relpaths):
            target = root / relpath
            for parent in reversed(target.relative_to(root).parents[:-1]):
                folder = root / parent
                if not folder.exists():
                    folder.mkdir()
                    made.append(folder)
            with open(target, "xb") as out:  # "x": fails rather than replace an existing file
                added.append(target)
                out.write((staging / relpath).read_bytes())
    except BaseException:
        for path in reversed(added):
            path.unlink(missing_ok=True)
        for folder in reversed(made):
            shutil.rmtree(folder, ignore_errors=True)
        raise


def tree(name: str, paths: list[str], marks: Mapping[str, str] | None = None) -> str:
    """``paths`` under a ``name/`` root drawn as a tree; ``marks`` adds a note after a file."""
    nested: dict[str, dict] = {}
    for path in paths:
        node = nested
        for part in path.split("/"):
            node = node.setdefault(part, {})
    lines = [f"{name}/"]

    def walk(node: dict, prefix: str, at: str) -> None:
        entries = sorted(node.items(), key=lambda e: (not e[1], e[0]))  # folders first
        for index, (part, children) in enumerate(entries):
            last = index == len(entries) - 1
            path = f"{at}{part}"
            note = (marks or {}).get(path, "")
            label = f"{part}/" if children else part + (f"  ({note})" if note else "")
            lines.append(f"{prefix}{'└── ' if last else '├── '}{label}")
            walk(children, prefix + ("    " if last else "│   "), f"{path}/")

    walk(nested, "", "")
    return "\n".join(lines) + "\n"
