"""What a package is linted against: the target ROS distribution and the other workspace packages.

The workspace of a package is every package linted in the same run plus, when the package
lies under the ``src`` folder of a colcon workspace (a folder ``ws`` with ``ws/src``), every
package colcon would find there. For each one the index keeps its name, the interfaces of its
``msg/``, ``srv/`` and ``action/`` folders, and its top-level Python packages. Reading is
cheap (package.xml's name and three folder listings) and never raises.
"""

from __future__ import annotations

import os
import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from pathlib import Path

from pkgtool.knowledge.tables import DEFAULT_DISTRO
from pkgtool.workspace import listing

_NAME = re.compile(r"<name>\s*([^<\s]+)\s*</name>")
_KINDS = ("msg", "srv", "action")
_SUFFIXES = (".msg", ".srv", ".action", ".idl")
_NOT_MODULES = frozenset({"test", "tests", "launch", "resource", "build", "install", "log"})


@dataclass(frozen=True, slots=True)
class WorkspacePackage:
    """Another package of the workspace: its interfaces (kind -> names) and Python packages."""

    name: str
    interfaces: Mapping[str, frozenset[str]] = field(default_factory=dict)
    modules: frozenset[str] = frozenset()


@dataclass(frozen=True, slots=True)
class Context:
    """The target ``distro`` and the workspace's packages by name (the linted one included)."""

    distro: str = DEFAULT_DISTRO
    workspace: Mapping[str, WorkspacePackage] = field(default_factory=dict)

    def provider(self, module: str) -> str | None:
        """The workspace package whose Python package ``module`` is, if any."""
        return next((p.name for p in self.workspace.values() if module in p.modules), None)


def read_workspace_package(root: Path) -> WorkspacePackage:
    """Name (package.xml, else the folder), interfaces and Python packages of ``root``."""
    base = os.fspath(root)
    try:
        with open(os.path.join(base, "package.xml"), encoding="utf-8", errors="replace") as f:
            found = _NAME.search(f.read())
        name = found.group(1) if found else root.name
    except OSError:
        name = root.name
    listed = listing(base)
    interfaces = {}
    for kind in _KINDS:
        if any(entry.name == kind for entry in listed):
            names = frozenset(e.name.rsplit(".", 1)[0] for e in listing(os.path.join(base, kind))
                              if e.name.endswith(_SUFFIXES))
            if names:
                interfaces[kind] = names
    modules = frozenset(e.name for e in listed if e.name.isidentifier()
                        and e.name not in _NOT_MODULES and e.is_dir()
                        and os.path.isfile(os.path.join(e.path, "__init__.py")))
    return WorkspacePackage(name, interfaces, modules)


def colcon_src(root: Path) -> Path | None:
    """The ``src`` folder of the colcon workspace ``root`` is in, if any."""
    for folder in root.parents:
        if folder.name == "src" and folder.is_dir():
            return folder
    return None


def workspace_of(roots: Iterable[Path], searched: Iterable[Path] = ()
                 ) -> dict[str, WorkspacePackage]:
    """The workspace index of the packages at ``roots`` (absolute): they and their neighbours.

    A colcon ``src`` folder inside one of the ``searched`` folders (those discovery already
    walked) is not walked again.
    """
    from pkgtool.workspace import discover

    everything = set(roots)
    walked = tuple(searched)
    for source in {colcon_src(root) for root in everything} - {None}:
        assert source is not None
        if not any(source == top or top in source.parents for top in walked):
            everything.update(discover([str(source)], cwd=source).packages)
    found: dict[str, WorkspacePackage] = {}
    for root in sorted(everything):
        package = read_workspace_package(root)
        found.setdefault(package.name, package)
    return found
