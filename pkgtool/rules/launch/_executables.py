"""The executables an ament_python package installs into ``lib/<package>``, for launch rules."""

from __future__ import annotations

import posixpath

from pkgtool.model.installed import is_ament_python
from pkgtool.model.package import Package


def executables(package: Package) -> frozenset[str] | None:
    """Names the package installs into ``lib/<package>``, or None when that cannot be known.

    Console scripts of setup.py and setup.cfg count, and so do files that data_files copies
    into ``lib/<package>``. A malformed console script (ENT001's), anything dynamic
    (unevaluated keywords, ``scripts=``, a setup.cfg or pyproject.toml that did not parse or
    may declare scripts) makes the answer unknown, and so does a package colcon builds with
    CMake (another build type, or a CMakeLists.txt and none): CMake installs the executables
    then.
    """
    setup = package.setup_py
    if setup is None or "scripts" in setup.keywords or package.has_file("pyproject.toml"):
        return None
    if not is_ament_python(package):
        return None  # CMake installs its executables; a setup.py beside it is not run
    if any(setup.is_unresolved(k) for k in ("entry_points", "data_files", "**")):
        return None
    if package.has_file("setup.cfg") and package.setup_cfg is None:
        return None
    if not all(entry.valid for entry in setup.console_scripts):
        return None  # setuptools refuses the whole list (ENT001): nothing is installed
    names = {entry.name for entry in setup.console_scripts}
    option = package.setup_cfg.get("options.entry_points", "console_scripts") \
        if package.setup_cfg else None
    if option is not None:
        names.update(line.split("=", 1)[0].strip() for line in option.value.splitlines()
                     if "=" in line)
    library = f"lib/{package.name}"
    for entry in setup.data_files or ():
        if posixpath.normpath(entry.destination.strip("/")) == library:
            for source in entry.sources:
                names.update(posixpath.basename(m) for m in source.matches)
                if not source.is_glob:
                    names.add(posixpath.basename(source.pattern))
    return frozenset(names)
