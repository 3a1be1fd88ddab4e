"""Which packages to build and how to copy them into a job's workspace without trusting them.

Packages are found with :mod:`pkgtool.workspace` discovery and read with
:func:`pkgtool.model.package.load_package`; the copy follows no symlink out of a package,
skips special files and colcon's output folders, and stops at the submission caps.
"""

from __future__ import annotations

import hashlib
import os
import re
import shutil
import stat
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path

from pkgtool.grade.extract import ExtractLimits, SubmissionError
from pkgtool.model.package import load_package
from pkgtool.workspace import discover

_SKIPPED = frozenset({".git", "__pycache__", ".pytest_cache"})
_OUTPUT = frozenset({"build", "install", "log"})
"""colcon's output folders: skipped at a package's root unless they are Python packages."""
_SAFE_NAME = re.compile(r"^[A-Za-z0-9][A-Za-z0-9_.-]{0,99}$")


@dataclass(frozen=True, slots=True)
class SourcePackage:
    """A package found in a submission or workspace: its name, folder and declared deps."""

    name: str
    root: Path
    depends: frozenset[str]


def find_packages(tree: Path) -> list[SourcePackage]:
    """Every package under ``tree`` (or ``tree`` itself), named as its package.xml says."""
    found = []
    for root in discover(["."], cwd=Path(os.path.abspath(tree))).packages:
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
        _copy_tree(package.root, copies[package.name], limits, counter)
    return copies


def _copy_tree(source: Path, dest: Path, limits: ExtractLimits, counter: list[int]) -> None:
    real_root = os.path.realpath(source)
    for folder, dirs, files in os.walk(source):
        relative = Path(folder).relative_to(source)
        dirs[:] = [d for d in dirs if not _skipped(Path(folder) / d, relative == Path("."))]
        (dest / relative).mkdir(parents=True, exist_ok=True)
        for name in files:
            path = os.path.join(folder, name)
            info = os.lstat(path)
            if stat.S_ISLNK(info.st_mode):  # kept as a copy, and only when it stays inside
                path = os.path.realpath(path)
                if not (path.startswith(real_root + os.sep) and os.path.isfile(path)):
                    continue
                info = os.stat(path)
            if not stat.S_ISREG(info.st_mode):
                continue
            counter[0] += 1
            counter[1] += info.st_size
            if counter[0] > limits.max_files or counter[1] > limits.max_bytes:
                raise SubmissionError(f"the submission has more than {limits.max_files} files "
                                      f"or {limits.max_bytes // (1024 * 1024)} MB")
            shutil.copyfile(path, dest / relative / name, follow_symlinks=False)
            os.chmod(dest / relative / name, 0o755 if info.st_mode & 0o111 else 0o644)


def _skipped(folder: Path, at_root: bool) -> bool:
    name = folder.name
    if name in _SKIPPED or name.endswith(".egg-info") or folder.is_symlink():
        return True
    return at_root and name in _OUTPUT and not (folder / "__init__.py").is_file()


def tree_digest(path: Path) -> str:
    """SHA-256 over every entry's relative path, type, mode bits and content (or link target)."""
    digest = hashlib.sha256()
    if path.is_file():
        _hash_file(digest, path)
        return digest.hexdigest()
    for folder, dirs, files in os.walk(path):
        dirs.sort()
        for name in sorted(dirs + files):
            full = os.path.join(folder, name)
            info = os.lstat(full)
            digest.update(f"{os.path.relpath(full, path)}\0{info.st_mode:o}\0".encode())
            if stat.S_ISLNK(info.st_mode):
                digest.update(os.readlink(full).encode())
            elif stat.S_ISREG(info.st_mode):
                _hash_file(digest, Path(full))
    return digest.hexdigest()


def _hash_file(digest: "hashlib._Hash", path: Path) -> None:
    with open(path, "rb") as handle:
        for chunk in iter(lambda: handle.read(1 << 20), b""):
            digest.update(chunk)
