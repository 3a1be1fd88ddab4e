"""DEP007: an installed module imports a module next to it as if it were top-level."""

from __future__ import annotations

import posixpath
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rosdistro import keys_for_import, stdlib_modules
from pkgtool.model.installed import installed_modules, separate_projects
from pkgtool.model.modules import Import, PythonModule
from pkgtool.model.package import Package
from pkgtool.rules.imports import (ANY, console_script_files, declared, enclosing_package_import,
                                   installed_code, path_modules, python_package_of,
                                   beside_the_scripts, copied_beside_the_scripts,
                                   run_as_a_script, script_helpers)
from pkgtool.rules.dependencies._cmake_scripts import uninstalled_script_neighbours
from pkgtool.rules.registry import rule
from pkgtool.lazy_regex import lazy_pattern


@rule("DEP007", "sibling-module-import", Severity.ERROR,
      fix="Import it through its package: `from my_pkg.helpers import x` or `from .helpers "
          "import x`")
def sibling_module_import(package: Package) -> Iterator[Hit]:
    """An installed module imports a module of its own folder as a top-level module.

    ## What it does
    Reports unguarded absolute imports (`import helpers`, `from helpers import x`) in modules
    that setup.py installs, when `helpers.py` (or a `helpers/` package) sits in the same
    folder and is not itself installed as a top-level module (nor copied by data_files into
    `lib/<package>`, beside the console scripts, whose folder Python puts first on the
    path). Names of the standard library,
    of package.xml's dependencies and of third-party modules whose rosdep key package.xml
    declares are left alone (a `visualization.py` beside the module, with no
    `autolab-visualization-pip` declared, is the module meant), and so is
    a module importing its own name (`import rclpy` in `rclpy.py`): Python 3 imports are
    absolute, so those mean the real package, and so does the same import in the module's
    neighbours (`from record_impl import Base` next to a `record_impl.py` that wraps a compiled
    `record_impl` extension and imports it). Also reports, in the modules of a package folder
    below the top level (`my_pkg/filters/`), imports of its modules through the folder's bare
    name (`from filters.low_pass import smooth`, `from filters import low_pass`); importing
    the bare name alone (`import filters`, `from filters import smooth`) names no module of
    the folder and is left alone, and so is a folder beside a setup.py or pyproject.toml of
    its own (a project kept inside, pip-installed, importing its own top-level package).
    Fallbacks (`except ImportError:`, `if '.' in __name__:`) are guarded and never reported,
    and so are scripts kept in the package folder: a module that runs code at its top level
    (a call, an `if __name__ == '__main__':` block) that no console script runs and no module
    imports, run as `python3 path/to/it.py`, and the helpers only such scripts (or their
    helpers) of the same folder import, by their bare name. In a package built with CMake,
    reports the same mistake in the scripts `install(PROGRAMS ... DESTINATION lib/...)`
    installs: an import of a module or package beside the script in the source tree that
    CMakeLists.txt does not install (nor puts in a Python package with
    `ament_python_install_package`), when what it installs is known. And an import of a
    module of a folder data_files copies beside the console scripts that the copy leaves out
    (`from helpers.pose import x` when only `helpers/gait.py` goes into `lib/<package>/`).

    ## Why is this bad?
    `python3 my_pkg/node.py` puts the file's folder on `sys.path`, so the import works while
    developing. The console script that `ros2 run` starts imports `my_pkg.node`; nothing puts
    `my_pkg/` on the path and the node dies with `ModuleNotFoundError: No module named
    'helpers'`. Inside `my_pkg/filters/`, `filters.low_pass` works only while the folder above
    it is on the path (a script run next to it); installed it is `my_pkg.filters.low_pass`.
    A script CMake installs runs from `lib/<package>`, where only what CMake installed sits
    beside it.

    ## Example
    ```python
    # my_pkg/node.py
    from helpers import clamp
    ```

    ## Use instead
    ```python
    # my_pkg/node.py
    from my_pkg.helpers import clamp
    ```
    """
    installed = installed_modules(package)
    if installed is None:
        yield from uninstalled_script_neighbours(package)
        return
    modules = {module.path: module for module in package.modules}
    top_level = {name.split(".")[0] for name in installed}
    skip = top_level | stdlib_modules(package.context.distro) | declared(package, ANY).keys() | \
        beside_the_scripts(package)
    scripts = console_script_files(package)
    copied = copied_beside_the_scripts(package)
    helpers: dict[str, frozenset[str]] = {}  # by folder, worked out when first needed
    for module in installed_code(package):
        folder = posixpath.dirname(module.path)
        parent = python_package_of(package, module)
        if not folder or not parent:
            continue
        own_name = posixpath.basename(module.path)[:-3]
        exempt: bool | None = None  # worked out at the first import that would be reported
        on_path = path_modules(package, module)
        for imported in module.imports:
            top = imported.top_level
            missing = _not_copied(imported, copied) if not imported.guarded and not (
                top in top_level and f"{top}/__init__.py" not in copied) else None
            if missing is not None:
                yield Hit(imported.span, f"`{missing}` is not copied beside the console "
                          f"scripts: data_files copies only {_listed(copied, top)} of "
                          f"`{top}/` into `lib/{package.name}/`, so the import fails once "
                          "installed", f"Copy `{missing.replace('.', '/')}.py` with the rest "
                          f"of `{top}/` in data_files")
                continue
            if imported.guarded or not top or top in skip or any(
                    line < imported.span.line and top in names for line, names in on_path):
                continue  # a folder the module puts on sys.path first holds it
            inside = enclosing_package_import(package, parent, imported)
            sibling = None if inside else next(
                (f for f in (f"{folder}/{top}.py", f"{folder}/{top}/__init__.py")
                 if package.has_file(f)), None) or _namespace_folder(package, folder, top)
            if not inside and (sibling is None or top == own_name
                               or _third_party_meant(package, folder, imported, skip)
                               or _imports_itself(modules.get(f"{folder}/{top}.py"), top)):
                continue
            if exempt is None:
                if folder not in helpers:
                    helpers[folder] = script_helpers(package, folder, scripts)
                exempt = run_as_a_script(package, module, scripts) or \
                    module.path in helpers[folder]
            if exempt:
                break
            if inside:
                yield Hit(imported.span, f"`{top}` is the package `{inside[0]}` this module is "
                                         "in, not a top-level module: the import fails once "
                                         "installed", f"Import `{inside[1]}` instead")
                continue
            if sibling.endswith("/"):
                yield Hit(imported.span, f"`{top}` is a folder next to `{module.path}` (with "
                                         "no `__init__.py`), not a top-level module: the "
                                         "import fails once installed",
                          f"Import `{parent}.{top}`, and add `{sibling}__init__.py` so that "
                          "setup.py installs the folder")
                continue
            yield Hit(imported.span, f"`{top}` is a module next to `{module.path}`, not a "
                                     f"top-level module: the import fails once installed",
                      f"Import `{parent}.{top}` (or `.{top}`) instead")


def _not_copied(imported: Import, copied: frozenset[str]) -> str | None:
    """The dotted module ``imported`` names inside a folder data_files copies beside the
    scripts (``helpers.pose`` of ``from helpers.pose import x``) when that module is not among
    the copied files (the script's folder comes first on the path, so the copy is the package
    Python finds); None for anything else."""
    parts = (imported.module or "").split(".")
    if imported.level or len(parts) < 2 or not any(c.startswith(parts[0] + "/") for c in copied):
        return None
    path = "/".join(parts)
    return None if f"{path}.py" in copied or f"{path}/__init__.py" in copied else imported.module


def _listed(copied: frozenset[str], top: str) -> str:
    """The files of ``top/`` that are copied, for the message."""
    return ", ".join(f"`{c}`" for c in sorted(copied) if c.startswith(top + "/"))


def _namespace_folder(package: Package, folder: str, top: str) -> str | None:
    """``<folder>/<top>/`` when that folder holds Python files but no ``__init__.py`` (a
    folder ``find_packages()`` and ``packages=[...]`` leave out), else None; not when it is a
    Python project of its own (a ``setup.py`` or ``pyproject.toml``: a library kept in the
    package and pip-installed, whose code is a level further down)."""
    prefix = f"{folder}/{top}/"
    if f"{folder}/{top}" in separate_projects(package):
        return None
    return prefix if any(f.startswith(prefix) and f.endswith(".py") for f in package.files) \
        else None


def _third_party_meant(package: Package, folder: str, imported: Import,
                       skip: set[str] | frozenset[str]) -> bool:
    """True when ``imported`` (whose top-level name is a module of ``folder`` too) names a
    known third-party module and means it: package.xml declares one of its keys (in
    ``skip``), or the import names a submodule the sibling lacks (``from bokeh.plotting
    import figure`` beside a ``bokeh/`` holding no ``plotting``)."""
    keys = keys_for_import(imported.top_level, package.context.distro)
    if not keys:
        return False
    path = f"{folder}/{imported.module.replace('.', '/')}"
    return any(key in skip for key in keys) or not (
        package.has_file(f"{path}.py") or package.has_file(f"{path}/__init__.py"))


def _imports_itself(module: PythonModule | None, name: str) -> bool:
    """True when ``module`` (the file ``name.py``; a package folder importing its own name is
    DEP007's mistake again) imports the top-level ``name``: another module of that name exists
    (a compiled extension the file wraps), which its neighbours mean too."""
    return module is not None and any(i.top_level == name for i in module.imports)


_NEXT_TO = lazy_pattern(r"`(?P<top>\w+)` is a module next to .*")
_SIBLING_FIX = lazy_pattern(r"Import `(?P<full>[\w.]+)` \(or `\.\w+`\) instead")
_ENCLOSING = lazy_pattern(r"`(?P<top>\w+)` is the package `(?P<full>[\w.]+)` this module is in.*")


def installed_name(message: str, fix: str | None) -> tuple[str, str] | None:
    """(bare name, its installed dotted name) of a DEP007 hit's message and fix:
    (``helpers``, ``my_pkg.helpers``), (``filters``, ``my_pkg.filters``)."""
    sibling, written = _NEXT_TO.fullmatch(message), _SIBLING_FIX.fullmatch(fix or "")
    if sibling and written and written["full"].endswith("." + sibling["top"]):
        return sibling["top"], written["full"]
    enclosing = _ENCLOSING.fullmatch(message)
    return (enclosing["top"], enclosing["full"]) if enclosing else None
