"""Plain Python projects in a workspace: a setup.py and no package.xml, nor ROS package
files among what it installs (MAN020 reports the folders that do install them)."""

from __future__ import annotations

from pkgtool.model.package import Package
from pkgtool.model.setup_py import DataFile

MARKER_FOLDER = "share/ament_index/resource_index/packages"
"""Where an ament package installs the marker that makes it found."""


def ros_package_entry(package: Package) -> DataFile | None:
    """The first data_files entry installing package.xml or the ament index marker."""
    for entry in package.setup_py.data_files or () if package.setup_py else ():
        names = {name for source in entry.sources for name in (source.pattern, *source.matches)}
        if "package.xml" in names or entry.destination.rstrip("/") == MARKER_FOLDER:
            return entry
    return None


def plain_python_project(package: Package) -> bool:
    """True for a folder with a parsed setup.py, no package.xml and no ROS package files in
    its data_files: a Python project colcon builds as such (a library kept in a workspace)."""
    return package.setup_py is not None and package.setup_py.setup_span is not None and \
        not package.has_file("package.xml") and ros_package_entry(package) is None
