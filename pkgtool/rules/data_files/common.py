"""What the DAT rules share: data_files entries by destination, and folder tests."""

from __future__ import annotations

import posixpath
from collections.abc import Iterator

from pkgtool.model.package import Package
from pkgtool.model.setup_py import DataFile, DataSource

MARKER_FOLDER = "share/ament_index/resource_index/packages"
"""Where an ament_python package installs its ament index marker."""


def entries_to(package: Package, destination: str) -> Iterator[tuple[DataFile, DataSource]]:
    """data_files sources declared for ``destination`` (whether or not they exist)."""
    setup = package.setup_py
    for entry in setup.data_files or () if setup else ():
        if posixpath.normpath(entry.destination) == destination:
            yield from ((entry, source) for source in entry.sources)


def source_names(source: DataSource) -> set[str]:
    """Package-relative paths a source stands for: its matches, or its literal path."""
    return set(source.matches) or {posixpath.normpath(source.pattern)}


def is_folder(package: Package, path: str) -> bool:
    """True when ``path`` is a folder of the package (it holds files)."""
    prefix = path.rstrip("/") + "/"
    return any(f.startswith(prefix) for f in package.files)
