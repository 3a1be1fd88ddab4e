"""DEP007 in a package built with CMake: a script it installs into ``lib/<package>`` imports a
module that sits next to the script in the source tree but is not installed with it."""

from __future__ import annotations

import posixpath
from collections.abc import Iterator

from pkgtool.findings import Hit
from pkgtool.knowledge.rosdistro import keys_for_import, stdlib_modules
from pkgtool.model.cmake_install import installed_python_packages, program_sources
from pkgtool.model.installed import cmake_installed, cmake_text
from pkgtool.model.package import Package
from pkgtool.model.submodules import under
from pkgtool.rules.imports import ANY, declared, path_modules
from pkgtool.rules.ros1_platform import is_ros1_package


def uninstalled_script_neighbours(package: Package) -> Iterator[Hit]:
    """Imports, in the scripts ``install(PROGRAMS ... DESTINATION lib/...)`` installs, of a
    module or package beside the script that nothing installs: Python finds it next to the
    source, never next to the installed copy (``--symlink-install`` alone hides it)."""
    text = cmake_text(package)
    installed = cmake_installed(package)
    if text is None or installed is None or is_ros1_package(package):
        return
    skip = stdlib_modules(package.context.distro) | declared(package, ANY).keys() | \
        installed_python_packages(text) | {package.name}
    modules = {module.path: module for module in package.modules}
    for source, _ in program_sources(text):
        module = modules.get(source)
        if module is None:
            continue
        folder = posixpath.dirname(source)
        on_path = path_modules(package, module)
        told: set[str] = set()
        for imported in module.imports:
            top = imported.top_level
            if imported.guarded or imported.level or not top or top in skip or top in told or \
                    keys_for_import(top, package.context.distro) or \
                    any(line < imported.span.line and top in names for line, names in on_path):
                continue
            neighbour = _neighbour(package, folder, top)
            if neighbour is None or "." in installed or under(neighbour, installed):
                continue
            told.add(top)
            how = f"install(DIRECTORY {neighbour} DESTINATION lib/${{PROJECT_NAME}})" \
                if package.has_file(f"{neighbour}/__init__.py") or \
                not package.has_file(neighbour) else \
                f"install(FILES {neighbour} DESTINATION lib/${{PROJECT_NAME}})"
            yield Hit(imported.span,
                      f"`{top}` is next to `{source}` in the source tree, but CMakeLists.txt "
                      f"installs the script into `lib/{package.name}` without it: the "
                      "installed script's import fails (ModuleNotFoundError; only "
                      "`--symlink-install` hides it)",
                      f"Install `{neighbour}` beside the script: `{how}`")


def _neighbour(package: Package, folder: str, top: str) -> str | None:
    """The module file or package folder ``top`` of ``folder``, if the package has one."""
    base = posixpath.join(folder, top)
    if package.has_file(f"{base}.py"):
        return f"{base}.py"
    prefix = f"{base}/"
    return base if any(f.startswith(prefix) and f.endswith(".py") for f in package.files) \
        else None
