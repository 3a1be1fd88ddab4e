"""ENT002: a console script whose module setup.py does not install."""

from __future__ import annotations

import posixpath
import re
from collections.abc import Callable, Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rosdistro import (digits_differ, is_released_package, keys_for_import,
                                         modules_of_key, stdlib_modules, typo_of)
from pkgtool.model.installed import installed_modules, why_not_installed
from pkgtool.model.launch import python_folders
from pkgtool.model.package import Package
from pkgtool.model.setup_py import EntryPoint, Value
from pkgtool.rules.console_scripts import SCRIPT_GROUPS, problem, scripts_and_modules
from pkgtool.knowledge.interfaces import interfaces_of
from pkgtool.rules.imports import RUNTIME, declared, normalised_name
from pkgtool.rules.registry import rule
from pkgtool.rules.setup_values import checked_setup


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


_NO_MODULES_FOR_SCRIPTS = frozenset({"setuptools", "pytest", "wheel", "pip"})
"""Requirements that provide no module a package's script would name."""
_CORE = frozenset({"rclpy", "launch", "launch_ros", "ament_index_python", "launch_testing",
                   "launch_testing_ros", "ros2launch", "rosidl_default_runtime"})
"""ROS packages whose only Python package is the one of their name (or none)."""


def _provided_by_nothing(package: Package, entry: EntryPoint) -> Iterator[Hit]:
    """A hit when nothing can provide the entry's top-level module: not a package setup.py
    lists (one that does not exist is SET011's), not the standard library, no package of the
    workspace, no released ROS package, no module rosdep maps to a key, no requirement but
    setuptools' in ``install_requires`` (setup.py's or setup.cfg's), and no run-time
    dependency that may install it (any but interface packages, rclpy's own and Python keys
    of known modules)."""
    root = entry.module.split(".")[0]
    distro = package.context.distro
    setup = package.setup_py
    if setup is None or setup.is_unresolved("install_requires") or \
            setup.is_unresolved("**") or _requires_anything(setup.install_requires) or \
            package.setup_cfg is not None and \
            package.setup_cfg.get("options", "install_requires") is not None:
        return
    names = (*(setup.packages.names if setup.packages else ()), *(setup.py_modules or ()),
             *(setup.package_dir or {}))
    if root in {name.split(".")[0] for name in names} or root in stdlib_modules(distro) or \
            _in_the_workspace(package, root) or is_released_package(root, distro) or \
            keys_for_import(root, distro) or \
            any(_may_provide(key, root, distro) for key in declared(package, RUNTIME)):
        return
    yield Hit(entry.span, f"`{entry.module}` is not installed: neither this package, nor "
              "another of the workspace, nor a released ROS package, nor any dependency "
              f"package.xml or install_requires declares provides `{root}`: the script fails "
              "with ModuleNotFoundError", "Point the entry at a module this package installs, "
              "or declare the package that provides it")


def _requires_anything(required: Value | None) -> bool:
    """True when ``install_requires`` holds a requirement other than setuptools' own."""
    value = required.value if required is not None else ()
    lines = value.splitlines() if isinstance(value, str) else \
        value if isinstance(value, (list, tuple)) else ()
    names = {normalised_name(re.split(r"[\s<>=!~;\[@(]", str(line).strip(), maxsplit=1)[0])
             for line in lines if str(line).strip()}
    return not names <= _NO_MODULES_FOR_SCRIPTS


def _in_the_workspace(package: Package, root: str) -> bool:
    """True when a package of the workspace is named ``root`` or installs a Python package
    or namespace below it (``acme.utils`` for ``acme``)."""
    return root in package.context.workspace or package.context.provider(root) is not None or \
        any(module == root or module.startswith(f"{root}.")
            for other in package.context.workspace.values() for module in other.modules)


def _may_provide(key: str, root: str, distro: str) -> bool:
    """True when the declared ``key`` may install the module ``root``: it is named so, or
    its modules are not known (a ROS package's Python package may be named otherwise:
    ``urdfdom_py`` installs ``urdf_parser_py``)."""
    if key == root:
        return True
    if key in _CORE or interfaces_of(key, distro) is not None:
        return False
    modules = modules_of_key(key)
    return root in modules if modules else True


def _misspelt_beside_custom_commands(package: Package) -> Iterator[Hit]:
    """Hits for console scripts naming a module whose file does not exist, a typo away from
    the one module beside it so spelled (``dh_conventer`` for ``dh_converter.py``), in a
    setup.py whose ``cmdclass`` hides what it installs: custom commands add generated files,
    never a module named like a typo of a source file."""
    setup = checked_setup(package)
    if setup is None or "cmdclass" not in setup.keywords or setup.package_dir or \
            "ext_modules" in (*setup.keywords, *dict(setup.unresolved)) or \
            installed_modules(package) is not None:
        return
    for entry in setup.entry_points or ():
        if entry.group not in SCRIPT_GROUPS or problem(entry) or "." not in entry.module:
            continue
        path = entry.module.replace(".", "/")
        folder, _, name = path.rpartition("/")
        if not package.has_file(f"{folder}/__init__.py") or \
                package.has_file(f"{path}/__init__.py") or \
                any(f.startswith(f"{path}.") for f in package.files):  # .py, .pyx, .c
            continue
        beside = {f[len(folder) + 1:-3] for f in package.files
                  if f.startswith(f"{folder}/") and f.endswith(".py") and
                  "/" not in f[len(folder) + 1:]}
        meant = typo_of(name, beside)
        if meant is not None and not digits_differ(name, meant):
            fixed = f"{entry.module.rpartition('.')[0]}.{meant}"
            yield Hit(entry.span, f"`{entry.module}` is no module of the package: `{folder}/` "
                                  f"holds no `{name}.py` (did you mean `{meant}`?)",
                      f"Write `{fixed}:{entry.attr}`")


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
    no module rosdep knows, no requirement in `install_requires` but setuptools, no run-time
    dependency that may install it: any but interface packages, rclpy's own and Python keys
    of other modules) is reported too.

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
    if not entries:
        yield from _misspelt_beside_custom_commands(package)
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
