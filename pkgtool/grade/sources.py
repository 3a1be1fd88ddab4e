"""Which packages to build and how to copy them into a job's workspace without trusting them.

Copies walk the source with :mod:`pkgtool.safe_fs`: no symbolic link is followed out of the
copied folder (the folder itself included: a submission that is a link is refused), a file
link is copied as its target only when that target, read on the text alone and opened
component by component, is a regular file inside; special files are skipped; colcon's
output folders, ``.git`` and caches are left out; the caps of :class:`ExtractLimits` hold.
Packages are then found in the copy, which holds no link at all.
"""

from __future__ import annotations

import hashlib
import os
import stat
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import BinaryIO

from pkgtool.grade.extract import ExtractLimits, SubmissionError
from pkgtool.records import record
from pkgtool.safe_fs import (MB, Entry, TreeWriter, UnsafeFile, lexical_target, open_path,
                             walk_tree)
from pkgtool.model.package import load_package
from pkgtool.workspace import IGNORE_MARKERS, discover
from pkgtool.lazy_regex import lazy_pattern

_SKIPPED = frozenset({".git", "__pycache__", ".pytest_cache"})
_OUTPUT = frozenset({"build", "install", "log"})
"""colcon's output folders: skipped beside a package.xml unless they are Python packages."""
_SAFE_NAME = lazy_pattern(r"^[A-Za-z0-9][A-Za-z0-9_.-]{0,99}$")


@record
class SourcePackage:
    """A package found in a submission or workspace: its name, folder and declared deps."""

    name: str
    root: Path
    depends: frozenset[str]


def find_packages(tree: Path) -> list[SourcePackage]:
    """Every package in ``tree`` (or ``tree`` itself), named as its package.xml says.

    Only folders inside ``tree`` count: nothing above it is ever a package of it.
    """
    found = []
    top = Path(os.path.abspath(tree))
    for root in discover(["."], cwd=top).packages:
        if root != top and top not in root.parents:
            continue
        package = load_package(root)
        manifest = package.manifest
        depends = frozenset(d.name for d in manifest.dependencies) if manifest else frozenset()
        found.append(SourcePackage(package.name, root, depends))
    return found


def choose_target(packages: Sequence[SourcePackage], wanted: str | None) -> SourcePackage:
    """The package to grade: ``wanted`` by name, else the only one; SubmissionError otherwise."""
    names = ", ".join(f"`{p.name}`" for p in packages)
    if wanted:
        for package in packages:
            if package.name == wanted:
                return package
        raise SubmissionError(f"no package named `{wanted}` in the submission"
                              + (f" (found {names})" if names else ""))
    if len(packages) == 1:
        return packages[0]
    if not packages:
        raise SubmissionError("the submission holds no ROS package (no `package.xml` found)")
    raise SubmissionError(f"the submission holds several packages ({names}); "
                          "name the graded one with `package` in the rubric")


def with_dependencies(target: SourcePackage,
                      available: Iterable[SourcePackage]) -> list[SourcePackage]:
    """``target`` and, transitively, the packages of ``available`` it depends on."""
    by_name = {p.name: p for p in available}
    chosen, todo = {target.name: target}, [target]
    while todo:
        for name in sorted(todo.pop().depends):
            if name in by_name and name not in chosen:
                chosen[name] = by_name[name]
                todo.append(by_name[name])
    return list(chosen.values())


def copy_packages(packages: Iterable[SourcePackage], dest: Path,
                  limits: ExtractLimits = ExtractLimits()) -> dict[str, Path]:
    """Copy each package to ``dest/<name>``; returns name -> copied folder."""
    counter = [0, 0]
    copies = {}
    for package in packages:
        if not _SAFE_NAME.match(package.name) or ".." in package.name:
            raise SubmissionError(f"the package name {package.name!r} is not a valid ROS "
                                  "package name (letters, digits and underscores)")
        copies[package.name] = dest / package.name
        copy_tree(package.root, copies[package.name], limits, counter)
    return copies


def copy_tree(source: Path, dest: Path, limits: ExtractLimits = ExtractLimits(),
              counter: list[int] | None = None) -> None:
    """Copy the folder ``source`` to the new folder ``dest`` the careful way (see above).

    ``counter`` (files, bytes) carries the caps across several copies.
    """
    counter = counter if counter is not None else [0, 0]
    dest.mkdir(parents=True)
    writer = TreeWriter(dest)
    try:
        for entry in walk_tree(source, max_depth=limits.max_depth, keep=_keep):
            if stat.S_ISDIR(entry.info.st_mode):
                os.close(writer.folder(entry.parts))
                continue
            handle = _source_file(source, entry)
            if handle is None:
                continue
            with handle:
                info = os.fstat(handle.fileno())
                counter[0], counter[1] = counter[0] + 1, counter[1] + info.st_size
                if counter[0] > limits.max_files or counter[1] > limits.max_bytes:
                    raise SubmissionError(f"the submission has more than {limits.max_files} "
                                          f"files or {limits.max_bytes // MB} MB")
                writer.file(entry.parts, iter(lambda: handle.read(MB), b""),
                            executable=bool(info.st_mode & 0o111))
    except UnsafeFile as error:
        raise SubmissionError(f"`{source.name}` cannot be copied: {error}") from None


def _source_file(source: Path, entry: Entry) -> BinaryIO | None:
    """The open regular file behind ``entry`` (a file, or a link to one inside), or None."""
    try:
        if stat.S_ISREG(entry.info.st_mode):
            return entry.open()
        if stat.S_ISLNK(entry.info.st_mode):
            target = lexical_target(entry.parts[:-1], entry.readlink())
            return open_path(source, target) if target else None
    except (UnsafeFile, OSError):
        return None
    return None


def _keep(parts: tuple[str, ...], beside: frozenset[str], inside: frozenset[str]) -> bool:
    name = parts[-1]
    if name in _SKIPPED or name.endswith(".egg-info") or inside & IGNORE_MARKERS:
        return False
    return not (name in _OUTPUT and "package.xml" in beside and "__init__.py" not in inside)


def tree_digest(path: Path) -> str:
    """SHA-256 over every entry's relative path, type, mode bits and content (or link target).

    Nothing is followed: a link (the path itself included) counts by its target's text.
    """
    digest = hashlib.sha256()
    if path.is_symlink():
        digest.update(os.readlink(path).encode(errors="replace"))
    elif path.is_file():
        _hash(digest, open_path(path.parent, (path.name,)))
    else:
        for entry in walk_tree(path, max_depth=512):
            digest.update(f"{'/'.join(entry.parts)}\0{entry.info.st_mode:o}\0".encode())
            if stat.S_ISLNK(entry.info.st_mode):
                digest.update(entry.readlink().encode(errors="replace"))
            elif stat.S_ISREG(entry.info.st_mode):
                _hash(digest, entry.open())
    return digest.hexdigest()


def _hash(digest: "hashlib._Hash", handle: BinaryIO) -> None:
    with handle:
        for chunk in iter(lambda: handle.read(MB), b""):
            digest.update(chunk)
