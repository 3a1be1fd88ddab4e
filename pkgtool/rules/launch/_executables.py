"""The executables an ament_python package installs into ``lib/<package>``, for launch rules."""

from __future__ import annotations

import posixpath
import re

from pkgtool.model.cmake_install import (installed_executables, installed_programs,
                                         runs_install_code)
from pkgtool.model.installed import cmake_text, is_ament_python
from pkgtool.model.memo import per_package
from pkgtool.model.package import Package
from pkgtool.model.pyproject import pyproject_may_add_scripts
from pkgtool.model.scripts import library_entries, script_names, sibling_executables


def executables(package: Package, *, any_data: bool = False) -> frozenset[str] | None:
    """Names the package installs into ``lib/<package>``, or None when that cannot be known.

    Console scripts of setup.py and setup.cfg count, and so do the ``scripts=`` setup.py
    lists and files that data_files copies into ``lib/<package>``. A malformed console script
    (ENT001's), anything dynamic (unevaluated keywords, ``scripts=`` included, a setup.cfg or
    pyproject.toml that did not parse or may declare scripts) makes the answer unknown, and
    so does a package colcon builds with CMake (another build type, or a CMakeLists.txt and
    none): CMake installs the executables then. With ``any_data``, a data_files that could
    not be evaluated counts as installing every file of the package into ``lib/<package>``
    (data_files copies files under their own names): the names that may be there, for telling
    a name that cannot be.
    """
    names = console_scripts(package)
    setup = package.setup_py
    if names is None or setup is None:
        return None
    if setup.is_unresolved("data_files"):
        return names | {posixpath.basename(f) for f in package.files} if any_data else None
    copied = set()
    for entry in library_entries(setup, package.name):
        for source in entry.sources:
            copied.update(posixpath.basename(m) for m in source.matches)
            if not source.is_glob:
                copied.add(posixpath.basename(source.pattern))
    return names | copied


@per_package
def cmake_programs(package: Package) -> dict[str, str]:
    """Executable names a launch file may mean for the scripts a CMake package installs with
    ``install(PROGRAMS x.py ...)`` under their file names (``x`` -> ``x.py``), when its CMake
    files name ``x`` nowhere else (a target, a ``RENAME``, a component's ``EXECUTABLE``, a
    program of its own: ``install(PROGRAMS scripts/x.py scripts/x ...)``)."""
    text = cmake_text(package)
    if text is None or is_ament_python(package) or runs_install_code(text):
        return {}  # code run at install time may link `x` to `x.py`
    programs = installed_programs(text)
    return {name[:-3]: name for name in programs
            if name.endswith(".py") and name[:-3] not in programs and
            not re.search(rf"(?<![\w./-]){re.escape(name[:-3])}(?![\w.-])", text)}


@per_package
def cmake_executables(package: Package) -> frozenset[str] | None:
    """The executables a package CMake builds installs into ``lib/<package>``, when its
    CMakeLists.txt says so for certain (:func:`installed_executables`); None otherwise."""
    text = cmake_text(package)
    if text is None or is_ament_python(package):
        return None
    return installed_executables(text)


def console_scripts(package: Package) -> frozenset[str] | None:
    """The console scripts of setup.py and setup.cfg, or None when they cannot be known (see
    :func:`executables`)."""
    setup = package.setup_py
    if setup is None or pyproject_may_add_scripts(package.texts.get("pyproject.toml")) or \
            not is_ament_python(package):
        return None  # CMake installs its executables; a setup.py beside it is not run
    if package.has_file("setup.cfg") and package.setup_cfg is None:
        return None
    return script_names(setup, package.setup_cfg)


def installs_program(package: Package, owner: str, name: str) -> bool:
    """True when the package ``owner`` (this one, or one of its workspace) installs a program
    called ``name`` into ``lib/<owner>`` as far as pkgtool can tell: a console script or file
    setup.py installs there, or a target or program of its CMakeLists.txt."""
    if owner == package.name:
        text = cmake_text(package)
        programs = installed_programs(text) \
            if text is not None and not is_ament_python(package) else frozenset()
        return name in programs or name in (executables(package, any_data=True) or ()) or \
            name in (cmake_executables(package) or ())
    sibling = package.context.workspace.get(owner)
    return sibling is not None and (name in (sibling_executables(sibling) or ()) or
                                    name in (sibling.executables or ()))
