"""The files ament_copyright checks in a package, with their parsed headers."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.model.package import Package
from pkgtool.rules.style._run import readable_sources
from pkgtool.ament.copyright import Header, read_header


def headers(package: Package) -> Iterator[tuple[str, Header]]:
    """Non-empty checked .py files (not the setup.py beside package.xml) and their headers."""
    for path in readable_sources(package):
        text = package.texts[path]
        if path == "setup.py" or not text.strip():
            continue
        yield path, read_header(text)
