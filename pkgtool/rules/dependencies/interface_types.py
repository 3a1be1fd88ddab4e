"""What DEP008 and DEP009 share: the interfaces a package name stands for, where known.

Known are the package's own ``msg/``, ``srv/`` and ``action/`` folders, those of the other
packages of the workspace, and (for a jazzy target) the shipped table of the Jazzy interface
wheels (:mod:`pkgtool.knowledge.interfaces`), in that order. Anything else is unknown: no
finding.
"""

from __future__ import annotations

import posixpath

from pkgtool.knowledge.interfaces import KINDS, Interfaces, interfaces_of
from pkgtool.model.memo import per_package
from pkgtool.model.package import Package

_SUFFIXES = (".msg", ".srv", ".action", ".idl")


@per_package
def own_interfaces(package: Package) -> Interfaces:
    """Kind -> names of the interface files in the package's own top-level kind folders."""
    found: dict[str, set[str]] = {}
    for path in package.files:
        folder, name = posixpath.split(path)
        if folder in KINDS and name.endswith(_SUFFIXES):
            found.setdefault(folder, set()).add(name.rsplit(".", 1)[0])
    return {kind: frozenset(names) for kind, names in found.items()}


def interfaces_for(package: Package, name: str) -> Interfaces | None:
    """The interfaces of the package called ``name`` as seen from ``package``, or None."""
    if name == package.name:
        return own_interfaces(package) or None
    neighbour = package.context.workspace.get(name)
    if neighbour is not None and neighbour.interfaces:
        return neighbour.interfaces
    return interfaces_of(name, package.context.distro)
