"""Lint's persistent cache: each package's findings, reused while nothing they depend on changed.

See :mod:`pkgtool.cache.store` for the key and the files, :mod:`pkgtool.cache.serial` for how
findings are written (generically, so every field a finding carries survives) and
:mod:`pkgtool.cache.replay` for whole runs shown again.
"""

from __future__ import annotations

import os
import time
from pathlib import Path
from typing import NamedTuple

CACHE_FOLDER = ".pkgtool_cache"
"""The cache's default folder name, in the project root."""
_GITIGNORE = "# Created by pkgtool: the lint cache is never committed.\n*\n"


class Shown(NamedTuple):
    """What a lint run showed: its exit code, its report and its messages (to stderr); what
    :mod:`pkgtool.cache.replay` shows again."""

    code: int
    report: str
    messages: list[str]


def cache_folder(cache_dir: str | None, cwd: Path) -> Path:
    """The cache folder: ``cache_dir`` (``--cache-dir``), else ``$PKGTOOL_CACHE_DIR`` (both
    relative to ``cwd``), else ``.pkgtool_cache`` in the project root."""
    chosen = cache_dir or os.environ.get("PKGTOOL_CACHE_DIR")
    return cwd / chosen if chosen else project_root(cwd) / CACHE_FOLDER


def project_root(cwd: Path) -> Path:
    """The nearest folder from ``cwd`` up holding a pyproject.toml, else ``cwd``."""
    return next((folder for folder in (cwd, *cwd.parents)
                 if (folder / "pyproject.toml").is_file()), cwd)


def prepare(base: Path) -> bool:
    """Create the cache folder ``base`` and its ``lint`` folder; False when they cannot be (a
    read-only or full disk: linting still works, uncached). A cache folder pkgtool creates
    gets a ``.gitignore`` (never one the user named that exists already, ``--cache-dir .``)."""
    try:
        if not base.exists():
            base.mkdir(parents=True, exist_ok=True)
            (base / ".gitignore").write_text(_GITIGNORE, encoding="utf-8")
        (base / "lint").mkdir(exist_ok=True)
    except OSError:
        return False
    return True


def write_atomically(folder: Path, name: str, text: str) -> None:
    """Write ``text`` to ``folder/name`` through a temporary file renamed into place, so no
    reader ever sees it half-written; on a read-only or full disk, write nothing."""
    temporary = folder / f".tmp-{os.getpid()}-{time.time_ns()}-{name}"
    try:  # created exclusively: never another run's (tempfile costs a run ~5 ms to import)
        handle = os.open(temporary, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
    except OSError:
        return
    try:
        with os.fdopen(handle, "w", encoding="utf-8") as stream:
            stream.write(text)
        os.replace(temporary, folder / name)
    except OSError:
        try:
            os.unlink(temporary)
        except OSError:
            pass
