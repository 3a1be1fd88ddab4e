"""Bring a submission into a job's workspace without trusting it: never through a link, an
archive never unpacked by the grader itself."""

from __future__ import annotations

import json
import os
import sys
from pathlib import Path

from pkgtool.grade.extract import ExtractLimits, SubmissionError, is_archive, lone_archive
from pkgtool.safe_fs import MB, UnsafeFile, open_path, remove_tree
from pkgtool.grade.sandbox import Sandbox
from pkgtool.grade.sources import copy_tree


def stage(path: Path, box: Sandbox, limits: ExtractLimits = ExtractLimits()) -> Path:
    """Copy or unpack the submission ``path`` into ``<workspace>/submission``; returns it.

    A folder is copied the careful way of :func:`pkgtool.grade.sources.copy_tree`; an
    archive (or a folder holding only an archive) is copied as one regular file and unpacked
    inside the sandbox, as the job's uid, by :mod:`pkgtool.grade.extract`. The result holds
    no link.
    """
    tree = box.workspace / "submission"
    if not os.path.lexists(path):
        raise SubmissionError(f"`{path}` does not exist")
    if path.is_symlink():
        raise SubmissionError(f"`{path.name}` is a symbolic link; submit the folder or the "
                              "archive itself")
    archive = path if is_archive(path) else lone_archive(path)
    if archive is not None:
        _unpack(archive, box, tree, limits)
    elif path.is_dir():
        copy_tree(path, tree, limits)
        box.give(tree)
    else:
        raise SubmissionError(f"`{path.name}` is neither a folder nor a .zip/.tar.gz archive")
    return tree


def _unpack(archive: Path, box: Sandbox, tree: Path, limits: ExtractLimits) -> None:
    holder = box.workspace / "archive"
    holder.mkdir()
    copy = holder / ("submission" + _suffix(archive.name))
    try:
        _copy_file(archive, copy, limits.max_bytes)
        tree.mkdir()
        box.give(holder)
        box.give(tree)
        run = box.run([sys.executable, "-I", "-B", "-m", "pkgtool.grade.extract", str(copy),
                       str(tree)], box.workspace, box.base_env(), channel=True)
    finally:
        remove_tree(holder)
    try:
        answer = json.loads(run.channel.splitlines()[-1]) if run.channel.strip() else {}
    except ValueError:
        answer = {}
    if isinstance(answer, dict) and isinstance(answer.get("error"), str):
        raise SubmissionError(answer["error"])
    if not (isinstance(answer, dict) and isinstance(answer.get("files"), int)):
        why = run.limit or (run.output.strip().splitlines() or ["it crashed"])[-1]
        raise SubmissionError(f"`{archive.name}` could not be unpacked within the limits "
                              f"({why})")


def _suffix(name: str) -> str:
    lower = name.lower()
    return next(s for s in (".tar.gz", ".tgz", ".tar", ".zip") if lower.endswith(s))


def _copy_file(source: Path, dest: Path, max_bytes: int) -> None:
    """Copy one regular file (no link, no FIFO) of at most ``max_bytes``."""
    try:
        handle = open_path(source.parent, (source.name,))
    except UnsafeFile as error:
        raise SubmissionError(f"`{source.name}` is not a plain file: {error}") from None
    with handle, open(dest, "xb") as sink:
        copied = 0
        while chunk := handle.read(MB):
            copied += len(chunk)
            if copied > max_bytes:
                raise SubmissionError(f"`{source.name}` is larger than "
                                      f"{max_bytes // MB} MB")
            sink.write(chunk)
