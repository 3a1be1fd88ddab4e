"""Packages a package's robot description, world and RViz files name.

A URDF or xacro file includes other packages' files (``$(find other)/urdf/arm.xacro``) and
points at their meshes (``package://other/meshes/base.dae``); SDF worlds and RViz settings do
the same. Such a name is a package the package really uses, whatever its spelling looks like.
The files are read only when a rule asks (most runs never do), each once per package.
"""

from __future__ import annotations

from pkgtool.lazy_regex import lazy_pattern
from pkgtool.model.files import TextFile, read_text
from pkgtool.model.memo import per_package
from pkgtool.model.package import Package

DESCRIPTION_SUFFIXES = (".urdf", ".xacro", ".sdf", ".srdf", ".world", ".rviz")
"""Files naming other packages by ``$(find ...)`` or ``package://`` URIs."""
_NAMED = lazy_pattern(r"\$\(\s*find(?:-pkg-share)?\s+([A-Za-z][\w.-]*)\s*\)|"
                      r"package://([A-Za-z][\w.-]*)/")


@per_package
def described_packages(package: Package) -> frozenset[str]:
    """The packages the package's description, world and RViz files name (``$(find x)``,
    ``$(find-pkg-share x)``, ``package://x/...``); unreadable files name none."""
    names: set[str] = set()
    for relpath in package.files:
        if relpath.endswith(DESCRIPTION_SUFFIXES):
            read = read_text(package.root, relpath)
            if isinstance(read, TextFile):
                names.update(found.group(1) or found.group(2)
                             for found in _NAMED.finditer(read.text))
    return frozenset(names)
