"""ROS 1 packages run on ROS 1's platform, which the tables of ROS 2 distributions do not describe.

A catkin package kept beside ROS 2 ones (or linted alone) is built for Noetic, on Ubuntu 20.04:
Python 3.8 and NumPy 1.17. Names that newer Pythons or NumPy 2 removed (``collections.Iterable``,
the ``imp`` module, ``numpy.float``) still exist there, so the checks that judge names by a ROS 2
distribution's Python and NumPy leave them alone in such a package; typos stay typos. One that
depends on Python 2 keys (``python-serial``) is built for Melodic or older, on Python 2, whose
syntax Python 3 does not read.
"""

from __future__ import annotations

from pkgtool.knowledge.rosdistro import is_rosdep_key
from pkgtool.model.condition import applies
from pkgtool.model.package import Package


def is_ros1_package(package: Package) -> bool:
    """True for a ROS 1 (catkin) package: its manifest's build type or build tool is catkin."""
    return package.manifest is not None and package.manifest.is_ros1


def is_python2_package(package: Package) -> bool:
    """True for a ROS 1 package built for Python 2 (Melodic or older): one that depends on a
    Python 2 rosdep key of a library that has a Python 3 key too (``python-serial``, not
    Noetic's ``python-is-python3``; not under a condition the target rules out)."""
    return is_ros1_package(package) and any(
        dependency.name.startswith("python-") and
        is_rosdep_key("python3-" + dependency.name[len("python-"):]) and
        applies(dependency.condition, package.context.distro)
        for dependency in package.manifest.dependencies)  # type: ignore[union-attr]
