"""Unpack a submission archive (.zip, .tar, .tar.gz) safely, or refuse it with the reason.

Refused: absolute paths, ``..`` components, device files, more files or bytes than the caps,
and zip members whose compression ratio betrays a bomb. Links pointing out of the archive
(zip: any link) are skipped, not unpacked: a student's built workspace holds such links
(colcon's ``log/latest``, ``--symlink-install``), and a folder copy skips them the same way.
Nothing is written until every member has been checked.
"""

from __future__ import annotations

import os
import stat
import tarfile
import zipfile
from dataclasses import dataclass
from pathlib import Path, PurePosixPath

ARCHIVE_SUFFIXES = (".zip", ".tar", ".tar.gz", ".tgz")
MB = 1024 * 1024


class SubmissionError(Exception):
    """A submission that cannot be graded, with a message for the student."""


@dataclass(frozen=True, slots=True)
class ExtractLimits:
    """Caps on what one submission may unpack to."""

    max_files: int = 5000
    max_bytes: int = 200 * MB
    max_ratio: int = 200


def is_archive(path: Path) -> bool:
    """True when ``path`` names a file with an archive suffix pkgtool unpacks."""
    return path.is_file() and path.name.lower().endswith(ARCHIVE_SUFFIXES)


def extract(archive: Path, dest: Path, limits: ExtractLimits = ExtractLimits()) -> None:
    """Unpack ``archive`` into the existing folder ``dest``; SubmissionError when unsafe."""
    try:
        if archive.name.lower().endswith(".zip"):
            _extract_zip(archive, dest, limits)
        else:
            _extract_tar(archive, dest, limits)
    except (zipfile.BadZipFile, tarfile.TarError, EOFError, OSError) as error:
        raise SubmissionError(f"`{archive.name}` is not a readable archive: {error}") from None


def _check_name(name: str) -> str:
    """The member's relative POSIX path, or SubmissionError for absolute or escaping paths."""
    posix = name.replace("\\", "/")
    if posix.startswith("/") or (len(posix) > 1 and posix[1] == ":"):
        raise SubmissionError(f"archive entry `{name}` has an absolute path")
    parts = [p for p in PurePosixPath(posix).parts if p not in ("", ".")]
    if ".." in parts:
        raise SubmissionError(f"archive entry `{name}` points outside the submission (`..`)")
    return "/".join(parts)


def _count(limits: ExtractLimits, files: int, total: int) -> None:
    if files > limits.max_files:
        raise SubmissionError(f"the archive has more than {limits.max_files} files")
    if total > limits.max_bytes:
        raise SubmissionError(f"the archive unpacks to more than {limits.max_bytes // MB} MB")


def _extract_zip(archive: Path, dest: Path, limits: ExtractLimits) -> None:
    with zipfile.ZipFile(archive) as bundle:
        members, total = [], 0
        for info in bundle.infolist():
            relative = _check_name(info.filename)
            mode = info.external_attr >> 16
            if stat.S_ISLNK(mode):
                continue  # never unpacked as a link
            total += info.file_size
            _count(limits, len(members) + 1, total)
            if info.file_size > limits.max_ratio * max(info.compress_size, 1) + MB:
                raise SubmissionError(f"archive entry `{info.filename}` expands "
                                      f"{info.file_size // max(info.compress_size, 1)} times: "
                                      "refused as a zip bomb")
            members.append((info, relative, mode))
        written = 0
        for info, relative, mode in members:
            if not relative:
                continue
            target = dest / relative
            if info.is_dir():
                target.mkdir(parents=True, exist_ok=True)
                continue
            target.parent.mkdir(parents=True, exist_ok=True)
            with bundle.open(info) as source, open(target, "wb") as sink:
                while chunk := source.read(MB):
                    written += len(chunk)
                    _count(limits, 0, written)
                    sink.write(chunk)
            os.chmod(target, 0o755 if mode & 0o111 else 0o644)


def _extract_tar(archive: Path, dest: Path, limits: ExtractLimits) -> None:
    if not hasattr(tarfile, "data_filter"):
        raise SubmissionError("this Python cannot unpack tar archives safely; submit a .zip")
    with tarfile.open(archive, "r:*") as bundle:
        members, total = [], 0
        while (member := bundle.next()) is not None:  # sizes checked before data is read
            _check_name(member.name)
            total += member.size
            _count(limits, len(members) + 1, total)
            try:
                members.append(tarfile.data_filter(member, str(dest)))
            except (tarfile.AbsoluteLinkError, tarfile.LinkOutsideDestinationError):
                continue  # a link out of the submission: skipped
            except tarfile.FilterError as error:
                raise SubmissionError(f"archive entry `{member.name}` is refused: {error}") \
                    from None
        bundle.extractall(dest, members=members, filter="data")
