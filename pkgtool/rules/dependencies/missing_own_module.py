"""DEP010: an installed or test module imports a module or name of its own package that is
missing."""

from __future__ import annotations

import posixpath
import re
from collections.abc import Iterator
from difflib import get_close_matches

from pkgtool.findings import Hit, Severity
from pkgtool.model.installed import installed_modules, is_ament_python
from pkgtool.model.modules import Import
from pkgtool.model.package import Package
from pkgtool.model.setup_py import PACKAGE_DATA
from pkgtool.model.submodules import ignored, under
from pkgtool.rules.imports import (installed_code, shadowing_folders, source_path_module,
                                   test_code)
from pkgtool.rules.registry import rule


def _base(imported: Import, dotted: str, is_package: bool) -> str | None:
    """The absolute module an import names (its ``from`` part), resolving dots from the
    importing module ``dotted``; None when the dots go above the top."""
    if imported.level == 0:
        return imported.module
    parts = dotted.split(".") if is_package else dotted.split(".")[:-1]
    if imported.level - 1 >= len(parts):
        return None
    parts = parts[:len(parts) - (imported.level - 1)]
    return ".".join([*parts, imported.module] if imported.module else parts)


def _in_tree(package: Package, module: str) -> bool:
    """True when the package has a file or folder for the dotted ``module`` (it may be
    uninstalled for another reason, which other rules report), or may generate it: its name
    (the first of its names with no folder in the package) is in setup.py, CMakeLists.txt (an
    extension module CMake builds, ``pybind11_add_module(name ...)``) or a ``.gitignore`` (a
    module written at build time), or a ``.gitignore`` leaves out its file or a folder around
    it (code a script
    generates, ``flatc -o my_pkg/flatbuffers``, or the user copies in); or it lies in a git
    submodule that is not checked out (SYN005 says so); or it is a compiled extension module
    kept in the tree (``dsrbind.so``, ``dsrbind.cpython-312-x86_64-linux-gnu.so``)."""
    path = module.replace(".", "/")
    generated = [package.texts.get(f, "") for f in package.files
                 if f in ("setup.py", "CMakeLists.txt") or f.endswith(".gitignore")]
    folder, _, stem = path.rpartition("/")
    prefix = f"{folder}/{stem}." if folder else f"{stem}."
    missing = _first_missing(package, module.split("."))
    return package.has_file(f"{path}.py") or under(path, package.unfetched) or \
        ignored(f"{path}.py", package.ignores) or any(
        f.startswith(prefix) and f.endswith((".so", ".pyd")) for f in package.files) or any(
        f.startswith(f"{path}/") for f in package.files) or any(
        re.search(rf"\b{re.escape(missing)}\b", text) for text in generated)


def _first_missing(package: Package, parts: list[str]) -> str:
    """The first of a dotted name's parts with no folder or module in the package (``senors``
    of ``my_pkg.senors.imu``, whose ``my_pkg/senors/`` does not exist; ``Missing`` of
    ``my_pkg.talker.Missing``); the last part when all exist. Only that name can be one a
    build step generates."""
    for depth in range(1, len(parts)):
        folder = "/".join(parts[:depth])
        if not package.has_file(f"{folder}.py") and \
                not any(f.startswith(f"{folder}/") for f in package.files):
            return parts[depth - 1]
    return parts[-1]


def _left_out(package: Package, module: str, installed: dict[str, str]) -> str | None:
    """The subpackage of an installed package that holds ``module`` in the source tree but
    that setup.py does not install (none of its modules is installed), or None."""
    parts = module.split(".")
    for count in range(2, len(parts) + 1):
        parent, name = ".".join(parts[:count - 1]), ".".join(parts[:count])
        parent_file = installed.get(parent, "")
        if not parent_file.endswith("/__init__.py"):
            return None
        folder = f"{posixpath.dirname(parent_file)}/{parts[count - 1]}"
        if name not in installed and not any(m.startswith(f"{name}.") for m in installed) and \
                any(f.startswith(f"{folder}/") and f.endswith(".py") for f in package.files):
            return name
    return None


def _shipped_as_data(package: Package, subpackage: str) -> bool:
    """True when setup.py copies the files of ``subpackage``'s folder into its parent
    package as data: it has ``package_data`` and a pattern for the folder
    (``{'mylib': ['plugins/*']}``); the folder, without ``__init__.py``, then imports as a
    namespace package."""
    setup, folder = package.setup_py, subpackage.rpartition(".")[2]
    text = package.texts.get("setup.py", "")
    return setup is not None and any(k in setup.keywords for k in PACKAGE_DATA) and \
        (f"'{folder}/" in text or f'"{folder}/' in text)


def _shadowed(package: Package, path: str, root: str) -> bool:
    """True when ``root`` is also a module next to the file ``path``: run as a script, the
    file imports that one."""
    folder = posixpath.dirname(path)
    return any(package.has_file(posixpath.join(folder, name))
               for name in (f"{root}.py", f"{root}/__init__.py"))


@rule("DEP010", "missing-own-module", Severity.ERROR,
      fix="Import the module or name under the name it has (check the spelling), or write it")
def missing_own_module(package: Package) -> Iterator[Hit]:
    """An installed or test module imports a module or name of this package that does not
    exist.

    ## What it does
    For the unguarded imports of installed modules (and the absolute ones of test modules,
    `from my_pkg.talker import Talker` in `test/test_talker.py`, and of Python launch files)
    that name a module below
    one of the package's own installed top-level packages (`import my_pkg.utils`,
    `from my_pkg.utils import clamp`, `from .utils import clamp`), reports a module that
    setup.py does not install and that has no file in the package; a module of installed
    code in a subpackage that is in the source tree but that `packages` does not list (no
    module of it installed: `packages=['my_pkg']` with `my_pkg/models/`, or a folder
    without `__init__.py` that `find_packages()` skips), which imports only under
    `--symlink-install`; and a name that
    `from my_pkg.utils import name` takes from an installed module which neither defines it
    at its top level nor has it as a submodule. Modules with `from x import *`, a
    module-level `__getattr__`, or calls of `globals()`, `exec()` or `setattr()` are not
    judged on their names; a module named in setup.py, CMakeLists.txt (an extension module
    CMake builds) or a `.gitignore` (generated at build time), or whose file a `.gitignore`
    leaves out (`**/flatbuffers/`: code a script generates), is taken to exist, and an
    absolute import is left alone when a module of its first name sits next to the
    importing file (run as a script, the file imports that one). Also an installed module's
    import of an own module through folders above it, whose first name nothing provides
    (`from ws.action_demo.action_demo.client import Client` for the installed
    `action_demo.client`: the source tree's path).

    ## Why is this bad?
    The node dies at start-up with `ModuleNotFoundError` or `ImportError: cannot import
    name` (a test module fails to load, so `colcon test` reports an error): usually a helper
    module, class or function renamed (or never written) while the import kept the old name.

    ## Example
    ```python
    from my_pkg.utils import clamp   # the file is my_pkg/util.py
    ```

    ## Use instead
    ```python
    from my_pkg.util import clamp
    ```
    """
    installed = installed_modules(package)
    if not installed:
        return
    names = {file: name for name, file in installed.items()}
    roots = {name.split(".")[0] for name in installed} - shadowing_folders(package)
    tests = [*test_code(package), *(f.python for f in package.launch_files if f.python)]
    for module in [*installed_code(package), *tests]:
        dotted = names.get(module.path)
        for imported in module.imports if dotted or module in tests else ():
            if dotted is None and imported.level:
                continue  # a test's relative import: its own folder, not the package
            base = _base(imported, dotted or "", module.path.endswith("__init__.py"))
            meant = None if imported.guarded or not dotted else \
                source_path_module(package, module, imported)
            if meant is not None:
                yield Hit(imported.span, f"`{imported.module}` is a path of the source tree, "
                          "not a module: the import raises ModuleNotFoundError once installed, "
                          f"where the module is `{meant}`", f"Write `{meant}`")
                continue
            if imported.guarded or base is None or base.split(".")[0] not in roots or (
                    imported.level == 0 and _shadowed(package, module.path, imported.top_level)):
                continue
            if base not in installed:
                left_out = _left_out(package, base, installed) \
                    if dotted and is_ament_python(package) else None
                if left_out is not None and _shipped_as_data(package, left_out):
                    continue
                if left_out is not None:
                    yield Hit(imported.span, f"`{left_out}` is in the source tree, but setup.py "
                              "does not install it (`packages` does not list it): the import "
                              "works only with `colcon build --symlink-install`, and raises "
                              "ModuleNotFoundError once installed",
                              "List the subpackage: `packages=find_packages(exclude=['test'])`"
                              ", with an `__init__.py` in each of its folders")
                elif not _in_tree(package, base):
                    close = get_close_matches(base, list(installed), n=1)
                    hint = f" (did you mean `{close[0]}`?)" if close else ""
                    yield Hit(imported.span, f"`{base}` is not a module of this package"
                                             f"{hint}: the import raises ModuleNotFoundError")
                continue
            source = package.module(installed[base])
            if source is None or source.syntax_error or \
                    "__getattr__" in source.top_level_names or \
                    any("*" in i.names for i in source.imports) or \
                    re.search(r"\b(globals|exec|setattr)\(", package.texts.get(source.path, "")):
                continue
            for name in imported.names:
                submodule = f"{base}.{name}"
                if name != "*" and name not in source.top_level_names and \
                        submodule not in installed and not _in_tree(package, submodule):
                    close = get_close_matches(name, sorted(source.top_level_names), n=1)
                    hint = f" (did you mean `{close[0]}`?)" if close else ""
                    yield Hit(imported.span, f"`{base}` defines no `{name}`{hint}: the import "
                                             "raises ImportError")
