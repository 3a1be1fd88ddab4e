"""ENT002: a console script whose module setup.py does not install."""

from __future__ import annotations

import posixpath
import re
from collections.abc import Callable, Iterator

from packaging.utils import canonicalize_name

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rosdistro import (is_released_package, keys_for_import, modules_of_key,
                                         stdlib_modules, typo_of)
from pkgtool.model.installed import why_not_installed
from pkgtool.model.launch import python_folders
from pkgtool.model.package import Package
from pkgtool.model.setup_py import EntryPoint
from pkgtool.rules.console_scripts import scripts_and_modules
from pkgtool.rules.imports import ANY, RUNTIME, declared
from pkgtool.rules.registry import rule


def _own_roots(package: Package, modules: dict[str, str]) -> set[str]:
    """Top-level names that belong to this package: installed, in its tree, or its name."""
    roots = {name.split(".")[0] for name in modules}
    roots |= {f.split("/")[0] for f in package.files if "/" in f}
    roots |= {f[:-3] for f in package.files if "/" not in f and f.endswith(".py")}
    return roots | {package.name}


def _meant(package: Package, module: str, modules: dict[str, str]) -> str | None:
    """The installed module an entry outside this package's names stands for: ``talker``
    for ``my_pkg.talker``, or ``my_pkgs.talker`` (a misspelt or copied package name that
    package.xml does not declare) when ``my_pkg.talker`` is the one installed module so named
    below a top-level package."""
    near = [m for m in modules if m.endswith(f".{module}")]
    if len(near) == 1:
        return near[0]
    root, _, rest = module.partition(".")
    declared = {d.name for d in package.manifest.dependencies} if package.manifest else {root}
    near = [m for m in modules if rest and m.partition(".")[2] == rest]
    return near[0] if len(near) == 1 and root not in declared else None


def _undeclared_provider(package: Package, entry: EntryPoint) -> Iterator[Hit]:
    """A hit when the entry names a module of another workspace package that package.xml
    does not declare for run time (a `<test_depend>` installs nothing for `ros2 run`)."""
    root = entry.module.split(".")[0]
    providers = [other.name for other in package.context.workspace.values()
                 if root in other.modules and other.name != package.name]
    if len(providers) == 1 and providers[0] not in declared(package, RUNTIME):
        yield Hit(entry.span, f"`{entry.module}` is a module of the package `{providers[0]}`, "
                  "which package.xml does not declare for run time: the script fails with "
                  "ModuleNotFoundError where that package is not installed",
                  f"Add `<exec_depend>{providers[0]}</exec_depend>` to package.xml")


def _provided_by_nothing(package: Package, entry: EntryPoint) -> Iterator[Hit]:
    """A hit when nothing can provide the entry's top-level module: not a package setup.py
    lists (one that does not exist is SET011's), not the standard library, no package of the
    workspace, no released ROS package, no module rosdep maps to a key, and
    nothing package.xml or ``install_requires`` names."""
    root = entry.module.split(".")[0]
    distro = package.context.distro
    setup = package.setup_py
    if setup is None or setup.is_unresolved("install_requires") or setup.is_unresolved("**"):
        return
    required = setup.install_requires.value if setup.install_requires else ()
    wanted = {canonicalize_name(re.split(r"[\s<>=!~;\[]", str(r), maxsplit=1)[0])
              for r in (required if isinstance(required, (list, tuple)) else (required,))}
    names = (*(setup.packages.names if setup.packages else ()), *(setup.py_modules or ()),
             *(setup.package_dir or {}))
    listed = {name.split(".")[0] for name in names}
    if root in listed or root in stdlib_modules(distro) or package.context.provider(root) or \
            root in package.context.workspace or is_released_package(root, distro) or \
            keys_for_import(root, distro) or canonicalize_name(root) in wanted or \
            any(key == root or _unmapped_python_key(key) for key in declared(package, ANY)):
        return
    yield Hit(entry.span, f"`{entry.module}` is not installed: neither this package, nor "
              f"another of the workspace, nor a released ROS package, nor anything package.xml "
              f"or install_requires names provides `{root}`: the script fails with "
              "ModuleNotFoundError", "Point the entry at a module this package installs")


def _unmapped_python_key(key: str) -> bool:
    """True for a Python key (``python3-x``, ``x-pip``) whose modules pkgtool does not know:
    it may install a module of any name."""
    return (key.startswith("python3-") or key.endswith("-pip")) and not modules_of_key(key)


def _misspelt_root(package: Package, module: str, modules: dict[str, str]
                   ) -> Callable[[EntryPoint], Hit] | None:
    """How to report an entry whose top-level package is a typo of the one installed top-level
    package so spelled (``artth.operator`` for ``arith``) that package.xml does not
    declare, or None."""
    root, _, rest = module.partition(".")
    declared = {d.name for d in package.manifest.dependencies} if package.manifest else {root}
    own = typo_of(root, {name.split(".")[0] for name in modules}) \
        if root not in declared else None
    if own is None:
        return None
    fixed = f"{own}.{rest}" if rest else own

    def hit(entry: EntryPoint) -> Hit:
        return Hit(entry.span, f"`{module}` is not installed: this package installs no `{root}` "
                               f"(did you mean `{own}`?)",
                   f"Write `{fixed}:{entry.attr or 'main'}`" if fixed in modules else
                   f"Write `{own}` and the module's name")
    return hit


@rule("ENT002", "uninstalled-entry-point-module", Severity.ERROR,
      fix="Make setup.py install the module: list its package in `packages` (or use "
          "`find_packages()`), and give every package folder an `__init__.py`")
def uninstalled_entry_point_module(package: Package) -> Iterator[Hit]:
    """A console script names a module that setup.py does not install.

    ## What it does
    Works out which modules setup.py installs (explicit `packages`, `find_packages` with
    `where`/`include`/`exclude`, `find_namespace_packages`, `package_dir`, `py_modules`) and
    reports console scripts whose module is not among them, saying why: the file does not
    exist, a package list drops subpackages, an `__init__.py` is missing, a pattern excludes
    it. Modules outside this package's own top-level names are not judged, unless the name
    is an installed module without its package prefix (`talker` for `my_pkg.talker`), or
    with another package prefix that package.xml does not declare (`my_pkgs.talker`, or a
    prefix copied from another package, for the one installed `my_pkg.talker`), or a prefix
    a typo away from the one installed package so spelled (`artth.talker` for `arith`), or
    starts with the name of one of the package's Python package folders below the top
    (`nodes.talker` for a `my_pkg/nodes/` that holds no `talker`); a module of another
    package of the workspace counts when package.xml declares that package for run time
    (`<exec_depend>`, `<depend>`), not only for tests. A module outside them that nothing can
    provide (not the standard library, no package of the workspace, no released ROS package,
    no module rosdep knows, nothing package.xml or `install_requires` names, and no Python key
    package.xml declares whose modules are unknown) is reported too.

    ## Why is this bad?
    The build succeeds, but running the command fails with `ModuleNotFoundError`. With
    `colcon build --symlink-install` the source folder is on the path, so the mistake often
    shows only in a clean or release build.

    ## Example
    ```python
    setup(packages=[package_name],   # my_pkg/nodes/ is a subpackage
          entry_points={'console_scripts': ['talker = my_pkg.nodes.talker:main']})
    ```

    ## Use instead
    ```python
    setup(packages=find_packages(exclude=['test']),
          entry_points={'console_scripts': ['talker = my_pkg.nodes.talker:main']})
    ```
    """
    entries, modules = scripts_and_modules(package)
    roots = _own_roots(package, modules) if entries else set()
    # the package's Python package folders at any depth: an entry naming one names its code
    folders = {posixpath.basename(f) for f in python_folders(package.files)} if entries else set()
    listed = set(package.setup_py.py_modules or ()) if entries and package.setup_py else set()
    for entry in entries:
        if entry.module in modules:
            continue
        if entry.module.split(".")[0] not in roots and entry.module not in listed:
            meant = _meant(package, entry.module, modules)
            if meant is not None:  # `talker:main` for the installed `my_pkg.talker`
                yield Hit(entry.span, f"`{entry.module}` is not installed: the module is "
                                      f"`{meant}`", f"Write `{meant}:{entry.attr or 'main'}`")
            typo = None if meant else _misspelt_root(package, entry.module, modules)
            if typo is not None:
                yield typo(entry)
            if meant is None and typo is None:
                yield from _undeclared_provider(package, entry)
                if entry.module.split(".")[0] not in folders:
                    yield from _provided_by_nothing(package, entry)
            if meant is not None or typo is not None or \
                    entry.module.split(".")[0] not in folders:
                continue
        reason, exists = why_not_installed(package, entry.module)
        fix = None if exists else "Write the module, or point the entry at an existing one"
        yield Hit(entry.span, f"`{entry.module}` is not installed: {reason}", fix)
