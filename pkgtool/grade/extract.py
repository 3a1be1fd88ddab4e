"""Unpack a submission archive (.zip, .tar, .tar.gz) safely, or refuse it with the reason.

The grader never runs this as root: it runs as ``python -m pkgtool.grade.extract ARCHIVE DEST``
inside the job's sandbox, as the job's uid, under the job's limits (see ``unpack`` in
:mod:`pkgtool.grade.stage`). Every member is checked before anything is written; refused,
with the reason: absolute paths, ``..`` components, names that are not UTF-8 or too long,
folders nested too deep, a name used for a file and a folder or twice, devices and FIFOs,
more files or bytes than the caps, and zip members whose ratio betrays a bomb.

No link is ever created. A link member (symbolic or hard) whose target, read on the text
alone and component by component, names a regular file of the archive through plain
folders is unpacked as a copy of that file; every other link is skipped (a student's built
workspace holds links out of it: colcon's ``log/latest``, ``--symlink-install``). Files are
created with ``O_EXCL``/``O_NOFOLLOW`` below descriptors, so nothing outside DEST is reachable,
whatever tarfile or the interpreter's filters would have done.
"""

from __future__ import annotations

import json
import os
import stat
import sys
import tarfile
import zipfile
from collections.abc import Iterator
from pathlib import Path, PurePosixPath
from typing import Any

from pkgtool.records import record
from pkgtool.safe_fs import MB, TreeWriter, lexical_target

ARCHIVE_SUFFIXES = (".zip", ".tar", ".tar.gz", ".tgz")


class SubmissionError(Exception):
    """A submission that cannot be graded, with a message for the student."""


@record
class ExtractLimits:
    """Caps on what one submission may unpack to (name lengths in UTF-8 bytes)."""

    max_files: int = 5000
    max_bytes: int = 200 * MB
    max_ratio: int = 200
    max_depth: int = 64
    max_name: int = 255
    max_path: int = 1024


@record
class Member:
    """One archive entry: its path parts, kind (file, dir, link), size and origin."""

    parts: tuple[str, ...]
    kind: str
    size: int = 0
    executable: bool = False
    source: Any = None
    target: tuple[str, ...] | None = None


def is_archive(path: Path) -> bool:
    """True when ``path`` names a file with an archive suffix pkgtool unpacks."""
    return path.is_file() and path.name.lower().endswith(ARCHIVE_SUFFIXES)


def lone_archive(folder: Path) -> Path | None:
    """The archive ``folder`` holds when it is the folder's only visible entry (a regular file,
    not a link), else None: Gradescope, Moodle and hand-made folders often hold just the
    uploaded ``.zip``."""
    try:
        visible = [e for e in folder.iterdir() if not e.name.startswith(".")]
    except OSError:
        return None
    only = visible[0] if len(visible) == 1 else None
    if only is None or only.is_symlink():
        return None
    return only if is_archive(only) else None


def extract(archive: Path, dest: Path, limits: ExtractLimits = ExtractLimits()) -> int:
    """Unpack ``archive`` into the existing empty folder ``dest``; returns the files written.

    SubmissionError says why an archive is refused.
    """
    try:
        if archive.name.lower().endswith(".zip"):
            with zipfile.ZipFile(archive) as bundle:
                return _write(bundle, _plan(_zip_members(bundle, limits), limits), dest, limits)
        with tarfile.open(archive, "r:*") as tar:
            return _write(tar, _plan(_tar_members(tar, limits), limits), dest, limits)
    except UnicodeDecodeError:
        raise SubmissionError(f"`{archive.name}` has file names that are not valid UTF-8; "
                              "rename the files and pack the archive again") from None
    except (zipfile.BadZipFile, zipfile.LargeZipFile, tarfile.TarError, EOFError,
            OSError) as error:
        raise SubmissionError(f"`{archive.name}` is not a readable archive: {error}") from None


def _check_name(name: str, limits: ExtractLimits) -> tuple[str, ...]:
    """The member's path parts, or SubmissionError for a name that cannot be unpacked."""
    posix = name.replace("\\", "/")
    if posix.startswith("/") or (len(posix) > 1 and posix[1] == ":"):
        raise SubmissionError(f"archive entry `{name}` has an absolute path")
    parts = tuple(p for p in PurePosixPath(posix).parts if p not in ("", "."))
    if ".." in parts:
        raise SubmissionError(f"archive entry `{name}` points outside the submission (`..`)")
    try:
        encoded = [part.encode("utf-8") for part in parts]
    except UnicodeEncodeError:
        raise SubmissionError(f"archive entry {name!r} has a name that is not valid UTF-8; "
                              "rename it") from None
    if any(len(part) > limits.max_name for part in encoded):
        raise SubmissionError(f"archive entry `{name}` has a name longer than "
                              f"{limits.max_name} bytes")
    if sum(len(part) + 1 for part in encoded) > limits.max_path:
        raise SubmissionError(f"archive entry `{name[:80]}...` has a path longer than "
                              f"{limits.max_path} bytes")
    if len(parts) > limits.max_depth:
        raise SubmissionError(f"archive entry `{name[:80]}...` is nested more than "
                              f"{limits.max_depth} folders deep")
    return parts


def _zip_members(bundle: zipfile.ZipFile, limits: ExtractLimits) -> Iterator[Member]:
    for info in bundle.infolist():
        parts = _check_name(info.filename, limits)
        mode = info.external_attr >> 16
        if stat.S_ISLNK(mode):
            target = bundle.read(info)[:4096].decode("utf-8", "replace") \
                if info.file_size <= 4096 else ""
            yield Member(parts, "link", target=lexical_target(parts[:-1], target))
        elif info.is_dir():
            yield Member(parts, "dir")
        else:
            if info.file_size > limits.max_ratio * max(info.compress_size, 1) + MB:
                raise SubmissionError(f"archive entry `{info.filename}` expands "
                                      f"{info.file_size // max(info.compress_size, 1)} times: "
                                      "refused as a zip bomb")
            yield Member(parts, "file", info.file_size, bool(mode & 0o111), info)


def _tar_members(tar: tarfile.TarFile, limits: ExtractLimits) -> Iterator[Member]:
    while (info := tar.next()) is not None:  # headers only: sizes are checked before data
        parts = _check_name(info.name, limits)
        if info.isreg():
            yield Member(parts, "file", info.size, bool(info.mode & 0o111), info)
        elif info.isdir():
            yield Member(parts, "dir")
        elif info.issym() or info.islnk():
            base = parts[:-1] if info.issym() else ()
            yield Member(parts, "link", target=lexical_target(base, info.linkname))
        else:
            raise SubmissionError(f"archive entry `{info.name}` is refused: it is a device "
                                  "file or a FIFO, not a file or a folder")


def _plan(members: Iterator[Member], limits: ExtractLimits) -> list[Member]:
    """Every member checked (caps, name clashes) and links resolved, before any write."""
    kinds: dict[tuple[str, ...], str] = {}
    planned: list[Member] = []
    files = total = 0
    for member in members:
        if not member.parts:
            continue
        shown = "/".join(member.parts)
        for depth in range(1, len(member.parts)):
            if kinds.setdefault(member.parts[:depth], "dir") != "dir":
                raise SubmissionError(f"archive entry `{shown}` is inside "
                                      f"`{'/'.join(member.parts[:depth])}`, which is a file")
        known = kinds.get(member.parts)
        if known is not None and (known != "dir" or member.kind != "dir"):
            what = "a file and a folder" if "dir" in (known, member.kind) else "twice"
            raise SubmissionError(f"archive entry `{shown}` is {what}; each name may appear "
                                  "once")
        kinds[member.parts] = member.kind
        planned.append(member)
        if member.kind == "file":
            files, total = files + 1, total + member.size
            _count(limits, files, total)
    by_path = {m.parts: m for m in planned if m.kind == "file"}
    resolved = []
    for member in planned:
        if member.kind == "link":
            target = _file_behind(member.target, kinds)
            if target is None:
                continue  # a link that could lead out of the submission: skipped
            source = by_path[target]
            files, total = files + 1, total + source.size
            _count(limits, files, total)
            member = Member(member.parts, "file", source.size, source.executable,
                            source.source)
        resolved.append(member)
    return resolved


def _file_behind(target: tuple[str, ...] | None, kinds: dict[tuple[str, ...], str]) -> \
        tuple[str, ...] | None:
    """``target`` when it names a regular file member reached through plain folders."""
    if target is None or kinds.get(target) != "file":
        return None
    if any(kinds.get(target[:depth]) != "dir" for depth in range(1, len(target))):
        return None
    return target


def _count(limits: ExtractLimits, files: int, total: int) -> None:
    if files > limits.max_files:
        raise SubmissionError(f"the archive has more than {limits.max_files} files")
    if total > limits.max_bytes:
        raise SubmissionError(f"the archive unpacks to more than {limits.max_bytes // MB} MB")


def _write(bundle: zipfile.ZipFile | tarfile.TarFile, members: list[Member], dest: Path,
           limits: ExtractLimits) -> int:
    writer, written, files = TreeWriter(dest), 0, 0
    for member in members:
        if member.kind == "dir":
            os.close(writer.folder(member.parts))
            continue
        source = bundle.open(member.source) if isinstance(bundle, zipfile.ZipFile) \
            else bundle.extractfile(member.source)
        assert source is not None
        with source:
            written += writer.file(member.parts, _chunks(source, limits, written),
                                   executable=member.executable)
        files += 1
    return files


def _chunks(source: Any, limits: ExtractLimits, before: int) -> Iterator[bytes]:
    total = before
    while chunk := source.read(MB):
        total += len(chunk)
        _count(limits, 0, total)
        yield chunk


def main(argv: list[str]) -> int:
    """``python -m pkgtool.grade.extract ARCHIVE DEST``: the answer goes to the results fd."""
    archive, dest = Path(argv[0]), Path(argv[1])
    try:
        answer: dict[str, Any] = {"files": extract(archive, dest)}
    except SubmissionError as error:
        answer = {"error": str(error)}
    fd = int(os.environ.get("PKGTOOL_RESULTS_FD", "1"))
    os.write(fd, json.dumps(answer).encode() + b"\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
