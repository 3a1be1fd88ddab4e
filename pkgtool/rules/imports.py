"""What the DEP, LCH and PYC rules share: which imports need a package.xml key, which are declared.

An absolute import needs a key unless it is standard library (of the target distribution's
Python), one of the package's own modules, a module next to the importing file, a module of
the importing file's own package named through the package's bare name (DEP007's mistake), a
module of a folder of the package the importing file (or, for test code, a ``conftest.py``
above it) puts on ``sys.path`` before the import (:mod:`pkgtool.rules.sys_path`), or (in test
code) a module pytest puts on ``sys.path``; after the importing file puts another module's
folder on ``sys.path`` (``dirname(other_pkg.__file__)``), only ROS packages need a key.
Third-party names map to rosdep keys through rosdep's data
(:func:`pkgtool.knowledge.rosdistro.keys_for_import`); ROS names (released for the target, or
ROS-looking) to ROS packages; Python packages of workspace packages to those packages; a name
that is none of these is ``unknown`` and only ever gets a guessed key.
"""

from __future__ import annotations

import ast
import posixpath
from collections.abc import Iterable, Iterator
from functools import lru_cache

from pkgtool.knowledge.interfaces import KINDS, interface_kind, is_known_package
from pkgtool.knowledge.ros_names import looks_like_ros
from pkgtool.knowledge.rosdep import (ALTERNATIVE_KEYS, ROS1_PACKAGES, ROS_MODULE_PACKAGES,
                                      accepted_keys, brought_in, is_metapackage,
                                      package_for_ros_module, suggested_key)
from pkgtool.knowledge.rosdistro import (DISTROS, any_stdlib_module, close_names,
                                         digits_differ, is_released_package, is_rosdep_key,
                                         keys_for_import, stdlib_modules, typo_distance)
from pkgtool.model.ast_nodes import TRIES
from pkgtool.model.cmake_install import installed_python_packages
from pkgtool.model.context import Context
from pkgtool.model.installed import (DATA_FOLDERS, PROJECT_FILES, cmake_text, installed_data,
                                     installed_files, installed_modules, is_ament_python,
                                     separate_projects)
from pkgtool.model.launch import is_launch_file, python_folders
from pkgtool.model.manifest import Dependency
from pkgtool.model.setup_py import EntryPoint
from pkgtool.model.modules import Import, PythonModule
from pkgtool.model.memo import per_package, per_tree
from pkgtool.model.package import Package
from pkgtool.model.python_visitor import parse_tree
from pkgtool.records import record
from pkgtool.rules.optional_imports import optional_modules
from pkgtool.rules.ros1_platform import is_ros1_package
from pkgtool.rules.sys_path import outside_edits, sys_path_edits, vendored_edits
from pkgtool.rules.test_modules import is_test_code, test_files
from pkgtool.lazy_regex import lazy_pattern

RUNTIME = frozenset({"depend", "exec_depend", "run_depend"})
BUILD_ONLY = frozenset({"build_depend", "build_export_depend", "buildtool_depend",
                        "buildtool_export_depend"})
TEST = frozenset({"test_depend"})
ANY = RUNTIME | BUILD_ONLY | TEST


def dependency_cause(key: str) -> str:
    """The root cause "``key`` is misspelt": MAN021 states it for a run dependency that
    package.xml misspells, DEP008 for an import that miscases an interface package; DEP001
    and LCH002 hits on ``key`` declared nowhere are its consequences."""
    return f"misspelled-dependency:{key}"


def declaration_cause(tag: str, key: str) -> str:
    """The cause a mistaken ``<tag>`` states when what it means to declare is ``key`` (a
    misspelling, a pip name, a dependency kept inside ``<export>``): :func:`dependency_cause`
    for a run dependency, whose absence the imports and launch files then show; none for
    others (a ``<build_depend>`` leaves the imports without a run key anyway)."""
    return dependency_cause(key) if tag in RUNTIME and key else ""


@record
class Need:
    """An import that a package.xml key must provide.

    ``kind`` is ``ros``, ``third-party`` or ``unknown``; ``keys`` are the keys that provide
    it (the first is the one to suggest); for ``unknown`` the only key is a guess.
    """

    module: PythonModule
    imported: Import
    top: str
    kind: str
    keys: tuple[str, ...]

    @property
    def key(self) -> str:
        """The key to suggest."""
        return self.keys[0]

    @property
    def missing(self) -> str:
        """How a message names what is not declared: the package, or the module's key."""
        if self.key == self.top:
            return "not declared in package.xml"
        return f"its key `{self.key}` is not declared in package.xml"


def declared(package: Package, tags: frozenset[str], *, bringing: bool = True
             ) -> dict[str, Dependency]:
    """Keys declared with one of ``tags`` (``depend`` counts for every kind), first tag wins.

    With ``bringing``, packages a declared one brings in
    (:func:`~pkgtool.knowledge.rosdep.brought_in`: ``ament_lint_common``'s linters, a
    metapackage's members) count as declared by its entry; without, only what package.xml
    names does. Worked out once per package and question (the DEP rules ask ~30 times a
    package): treat as read-only.
    """
    kept = _kept_declared(package)
    if (tags, bringing) not in kept:
        kept[tags, bringing] = _declared(package, tags, bringing)
    return kept[tags, bringing]


@per_package
def _kept_declared(package: Package) -> dict[tuple[frozenset[str], bool], dict[str, Dependency]]:
    return {}


def _declared(package: Package, tags: frozenset[str], bringing: bool) -> dict[str, Dependency]:
    found: dict[str, Dependency] = {}
    if package.manifest is None:
        return found
    for dependency in package.manifest.dependencies:
        if (dependency.tag in tags or dependency.tag == "depend") and dependency.name:
            found.setdefault(dependency.name, dependency)
    if bringing:
        for name, dependency in list(found.items()):
            for other in brought_in(name):
                found.setdefault(other, dependency)
    return found


def declaration(key: str, dependency: Dependency) -> str:
    """How a message names the entry declaring ``key``: its tag, or the entry bringing it in."""
    tag = dependency.tag
    if dependency.name == key:
        return f"`<{tag}>`"
    return f"`<{tag}>{dependency.name}</{tag}>` (which brings it in)"


@record
class _Layout:
    """Top-level Python names, folders holding ``__init__.py``, and each folder's entries."""

    names: frozenset[str]
    packages: frozenset[str]
    children: dict[str, frozenset[str]]


@lru_cache(maxsize=64)
def _layout(files: tuple[str, ...]) -> _Layout:
    names: set[str] = set()
    packages = python_folders(files)
    children: dict[str, set[str]] = {}
    for path in files:
        parts = path.split("/")
        for depth in range(len(parts)):
            entry = parts[depth]
            leaf = depth == len(parts) - 1
            children.setdefault("/".join(parts[:depth]), set()).add(
                entry[:-3] if leaf and entry.endswith(".py") else entry)
        if not path.endswith(".py") or is_launch_file(path, packages):
            continue
        if len(parts) == 1:
            names.add(parts[0][:-3])
        elif parts[0] in packages or not looks_like_ros(parts[0]):
            names.add(parts[0])
            if parts[0] == "src" and len(parts) > 2:
                names.add(parts[1])
    return _Layout(frozenset(names), packages,
                   {k: frozenset(v) for k, v in children.items()})


@per_package
def own_modules(package: Package) -> frozenset[str]:
    """Top-level names the package itself provides (never need a key).

    Modules at the top of a separate Python project inside the package (scripts and examples
    import them from the source tree) are, and so are the Python packages its CMakeLists.txt
    installs with ``ament_python_install_package`` (from any folder). A data folder installed
    by mistake under the name of another provider's module (:func:`shadowing_folders`) is not:
    imports of that name mean the other module.
    """
    layout = _layout(package.files)
    names = set(layout.names) | {package.name}
    cmake = package.texts.get("CMakeLists.txt")
    if cmake:
        names.update(installed_python_packages(cmake))
    for folder in separate_projects(package):
        names.update(entry for entry in layout.children.get(folder, ())
                     if package.has_file(f"{folder}/{entry}.py") and entry != "setup"
                     or f"{folder}/{entry}" in layout.packages)
    installed = installed_modules(package)
    if installed:
        names.update(name.split(".")[0] for name in installed)
    return frozenset(names - shadowing_folders(package))


def provided_elsewhere(name: str, context: Context) -> bool:
    """True when ``name`` is a module the standard library, ROS or rosdep provides."""
    return (name in _stdlib(context.distro) or is_released_package(name, context.distro)
            or bool(keys_for_import(name, context.distro)))


@per_package
def shadowing_folders(package: Package) -> frozenset[str]:
    """Data folders (``launch/``, ``test/``) holding Python files or an ``__init__.py`` that are
    named like another provider's module (``launch``): never the package's own code."""
    folders = {p.split("/")[0] for p in package.files if "/" in p and p.endswith(".py")}
    return frozenset(n for n in folders & DATA_FOLDERS if n != package.name
                     and provided_elsewhere(n, package.context))


def _siblings(package: Package, path: str) -> frozenset[str]:
    return _layout(package.files).children.get(posixpath.dirname(path), frozenset())


def path_modules(package: Package, module: PythonModule) -> list[tuple[int, frozenset[str]]]:
    """What the folders of the package that ``module`` puts on ``sys.path`` hold (their
    ``.py`` modules and the folders with Python files below them), each with the line of
    the edit; also those the ``__init__.py`` of its package and of the packages around it
    puts there, its own folder or one around it when some module of the package puts it
    there (the module that imports it by its bare name, having done so), and for test code
    those of the ``conftest.py`` files of its folder and the folders above it (all run
    first: line 0)."""
    edits = sys_path_edits(package)
    found = [(line, folder) for line, folder in edits.get(module.path, ())]
    folder = posixpath.dirname(module.path)
    found += [(0, edited) for edited in sorted({edited for made in edits.values()
                                               for _, edited in made})
              if edited == folder or folder.startswith(f"{edited}/")]  # its importers did
    while edits and folder and package.has_file(f"{folder}/__init__.py"):
        init = f"{folder}/__init__.py"  # runs before any module of its package
        if init != module.path:
            found.extend((0, edited) for _, edited in edits.get(init, ()))
        folder = posixpath.dirname(folder)
    if edits and is_test_code(package, module):
        folder = posixpath.dirname(module.path)
        while True:
            conftest = posixpath.join(folder, "conftest.py")
            if conftest != module.path:
                found.extend((0, edited) for _, edited in edits.get(conftest, ()))
            if not folder:
                break
            folder = posixpath.dirname(folder)
    return [(line, _folder_modules(package, folder)) for line, folder in found]


def _folder_modules(package: Package, folder: str) -> frozenset[str]:
    """The names importable from ``folder`` on ``sys.path``: its ``.py`` files and the
    folders holding Python files below it."""
    prefix = f"{folder}/" if folder else ""
    return frozenset(rest[:-3] if "/" not in rest else rest.split("/")[0]
                     for path in package.files if path.startswith(prefix) and path.endswith(".py")
                     for rest in (path[len(prefix):],))


@per_package
def installed_names(package: Package) -> dict[str, str]:
    """Package-relative file -> the dotted name setup.py installs it as (empty when unknown)."""
    return {file: name for name, file in (installed_modules(package) or {}).items()}


def python_package_of(package: Package, module: PythonModule) -> str:
    """The dotted name of the installed Python package ``module`` belongs to (``my_pkg.sub``
    for ``my_pkg/sub/__init__.py`` and ``my_pkg/sub/x.py``); empty when not installed."""
    dotted = installed_names(package).get(module.path, "")
    return dotted if module.path.endswith("/__init__.py") else dotted.rpartition(".")[0]


def absolute_module(module: str | None, level: int, package: str) -> str:
    """The module a ``from`` import of ``module`` with ``level`` leading dots names, relative
    to the Python package ``package`` it is in when it starts with dots."""
    if not level:
        return module or ""
    parts = package.split(".")
    parts = parts[:len(parts) - level + 1]
    return ".".join([*parts, *([module] if module else [])])


def enclosing_package_import(package: Package, owner: str, imported: Import
                             ) -> tuple[str, str] | None:
    """The package and the module of it that ``imported`` names through the package's bare name
    from inside it (``my_pkg.filters`` and ``my_pkg.filters.low_pass`` for ``from
    filters.low_pass import smooth`` or ``from filters import low_pass`` in ``my_pkg/filters/``,
    ``owner`` being the module's package), for a package below the top level; None otherwise.
    Running
    a script next to ``filters/`` puts it on ``sys.path`` as a top-level package; installed,
    only ``my_pkg`` is there. Importing the bare package (``import filters``, ``from filters
    import smooth``) names no module of it and may mean another top-level module, and so may a
    name of the standard library or of a third-party module rosdep knows."""
    top, parts = imported.top_level, owner.split(".")
    if not top or top not in parts[1:] or top in _stdlib(package.context.distro) or (
            keys_for_import(top, package.context.distro)):
        return None
    installed = installed_modules(package) or {}
    rest = imported.module.split(".")[1:]
    base = _enclosing_base(parts, top)
    if not base or kept_project_import(package, owner, imported):
        return None
    named = [".".join([base, *rest])] if rest else [f"{base}.{n}" for n in imported.names]
    found = next(((base, name) for name in named if name in installed), None)
    return found if found is None or not rest or \
        _provides(package, installed, found[1], imported.names) else None


def _enclosing_base(parts: list[str], top: str) -> str:
    """The dotted name of the innermost package of ``parts`` (a module's package, split)
    named ``top``, below the top level; empty when there is none."""
    return next((".".join(parts[:end]) for end in range(len(parts), 1, -1)
                 if parts[end - 1] == top), "")


def kept_project_import(package: Package, owner: str, imported: Import) -> bool:
    """True when ``imported`` names, by its bare name, a package around its module (``owner``)
    that sits in a folder with a setup.py or pyproject.toml of its own: a project kept inside
    (vendored PointPillars), installed by pip, whose top-level package it is."""
    base = _enclosing_base(owner.split("."), imported.top_level) if imported.top_level else ""
    init = (installed_modules(package) or {}).get(base, "") if base else ""
    above = posixpath.dirname(posixpath.dirname(init))
    return bool(above) and any(package.has_file(f"{above}/{name}") for name in PROJECT_FILES)


def _provides(package: Package, installed: dict[str, str], module: str,
              names: tuple[str, ...]) -> bool:
    """True when the installed ``module`` defines one of ``names`` or has it as a submodule:
    ``from launch.actions import ExecuteProcess`` in ``my_pkg/launch/`` whose ``actions``
    defines no ``ExecuteProcess`` means ROS's ``launch``, whatever the folder is called."""
    if not names or "*" in names:
        return True
    source = next((m for m in package.modules if m.path == installed[module]), None)
    return source is None or any(name in source.top_level_names or f"{module}.{name}" in installed
                                 for name in names)


_COLLECTED = lazy_pattern(r"(?:test_.*|.*_test|conftest)\.py")


@per_package
def pytest_path_modules(package: Package) -> frozenset[str]:
    """Modules pytest's default ``prepend`` import mode lets every test module import.

    For each collected file (``test_*.py``, ``*_test.py``, ``conftest.py``) pytest puts its
    first folder upwards without ``__init__.py`` on ``sys.path`` for the whole session, so a
    helper module there (``test/temporary_environment.py``) imports by its bare name.
    """
    layout = _layout(package.files)
    files = set(package.files)
    folders: set[str] = set(_cmake_test_path(package))
    for path in package.files:
        if _COLLECTED.fullmatch(posixpath.basename(path)):
            folder = posixpath.dirname(path)
            while folder and folder in layout.packages:
                folder = posixpath.dirname(folder)
            folders.add(folder)
    names: set[str] = set()
    for folder in folders:
        prefix = folder + "/" if folder else ""
        names.update(entry for entry in layout.children.get(folder, ())
                     if prefix + entry + ".py" in files or prefix + entry in layout.packages)
    return frozenset(names)


_TEST_PYTHONPATH = lazy_pattern(r"PYTHONPATH=([^\s\")]+)")
_SOURCE_FOLDER = lazy_pattern(r"\$\{(?:CMAKE_CURRENT_SOURCE_DIR|CMAKE_SOURCE_DIR|"
                              r"PROJECT_SOURCE_DIR|CMAKE_CURRENT_LIST_DIR)\}/?")


def _cmake_test_path(package: Package) -> Iterator[str]:
    """Package folders a CMakeLists.txt puts on its tests' ``PYTHONPATH``
    (``ament_add_pytest_test(... APPEND_ENV PYTHONPATH=${CMAKE_SOURCE_DIR}/scripts)``)."""
    text = cmake_text(package)
    for found in _TEST_PYTHONPATH.finditer(text or ""):
        for part in found.group(1).replace(";", ":").split(":"):
            folder = _SOURCE_FOLDER.match(part)
            rest = part[folder.end():] if folder else "$"
            if "$" not in rest and not rest.startswith(".."):
                yield "" if posixpath.normpath(rest or ".") == "." else posixpath.normpath(rest)


def installed_code(package: Package) -> list[PythonModule]:
    """Non-test modules that colcon installs
    (:func:`~pkgtool.model.installed.installed_files`; a module named like a test counts as
    test code only where :func:`~pkgtool.rules.test_modules.test_files` says so), and those a
    console script names that setup.py leaves out (a folder without ``__init__.py``: ENT002
    says so, and their imports are checked now rather than once that is fixed)."""
    files, tests = installed_files(package), test_files(package)
    scripts = console_script_files(package)
    meant = _console_script_sources(package)
    return [m for m in package.modules if (m.path in files or m.path in meant)
            and (m.path not in tests or m.path in scripts)]


def _console_script_sources(package: Package) -> frozenset[str]:
    """The files the console scripts' modules that setup.py does not install would be in
    (``pkg/node.py`` for ``pkg.node:main``), in an ament_python package whose installed
    modules are known."""
    entries = package.setup_py.entry_points if package.setup_py else None
    installed = installed_modules(package) if entries and is_ament_python(package) else None
    if installed is None:
        return frozenset()
    return frozenset(f"{e.module.replace('.', '/')}.py" for e in entries or ()
                     if e.group == "console_scripts" and e.module and e.module not in installed)


def entry_points_installed(package: Package, group: str) -> list[tuple[EntryPoint, str]]:
    """Entry points of ``group`` whose module setup.py installs, each with the module's file."""
    entries = package.setup_py.entry_points if package.setup_py else None
    installed = installed_modules(package) or {}
    return [(e, installed[e.module]) for e in entries or ()
            if e.group == group and e.module in installed]


def _entry_point_files(package: Package, group: str) -> frozenset[str]:
    return frozenset(file for _, file in entry_points_installed(package, group))


@per_package
def pytest_plugins(package: Package) -> frozenset[str]:
    """Files of modules that a ``pytest11`` entry point names: pytest loads them, nothing else."""
    return _entry_point_files(package, "pytest11")


@per_package
def console_script_files(package: Package) -> frozenset[str]:
    """Files of modules a console script runs: installed nodes, even when named ``*_test.py``."""
    return _entry_point_files(package, "console_scripts")


def run_as_a_script(package: Package, module: PythonModule,
                    scripts: frozenset[str] | None = None) -> bool:
    """True for a script kept in the package folder: it runs code at its top level (a call,
    or an ``if __name__ == '__main__':`` block), no console script runs it and no module of
    the package imports it. Run as ``python3 path/to/it.py``, its folder is on ``sys.path``
    and its neighbours import as top-level modules. ``scripts``: the files console scripts
    run (:func:`console_script_files`, when the caller has them)."""
    if module.path in (console_script_files(package) if scripts is None else scripts):
        return False
    return runs_code_at_its_top(package, module) and not importers_of(package, module)


def script_helpers(package: Package, folder: str, scripts: frozenset[str]) -> frozenset[str]:
    """The modules of ``folder`` that only scripts of the folder import, by their bare name
    (``import detector``), or helpers of theirs (``run_me.py`` imports ``utils``, which
    imports ``policy``, which may import ``utils`` back): they run with the scripts, their
    folder on ``sys.path`` (no console script runs them, nothing imports them through the
    package). The largest such set whose members a script reaches through such imports."""
    here = [m for m in package.modules if posixpath.dirname(m.path) == folder and
            m.path not in scripts]
    loaders = {m.path: importers_of(package, m) for m in here}
    runs = {m.path for m in here
            if not loaders[m.path] and runs_code_at_its_top(package, m)}  # run_as_a_script
    links: dict[str, set[str]] = {}
    for module in here:
        if module.path in runs:
            continue
        name = posixpath.basename(module.path)[:-3]
        importers = loaders[module.path]
        if importers and all(posixpath.dirname(path) == folder and
                             {i.module for i in imports} == {name}
                             for path, imports in importers.items()):
            links[module.path] = set(importers)
    helpers = set(links)
    while dropped := {path for path in helpers if not links[path] <= runs | helpers}:
        helpers -= dropped
    reached: set[str] = set()
    todo = [path for path in helpers if links[path] & runs]
    while todo:
        path = todo.pop()
        if path not in reached:
            reached.add(path)
            todo.extend(other for other in helpers if path in links[other])
    return frozenset(reached)


def runs_code_at_its_top(package: Package, module: PythonModule) -> bool:
    """True when ``module`` runs code at its top level: a call, also one anywhere inside a
    top-level loop, ``with``, ``if`` or ``try`` block (``for name in os.listdir(...): if
    is_red(name):``; not in ``except`` handlers, nor one that only reports, as a library's
    ``warnings.warn`` about a missing import), or an ``if __name__ == '__main__':`` block."""
    tree = parse_tree(module.path, package.texts.get(module.path, ""))
    return isinstance(tree, ast.Module) and any(
        _called(s) or isinstance(s, ast.If) and "__main__" in ast.unparse(s.test) or
        isinstance(s, _BLOCKS) and any(isinstance(n, ast.Call) and not _notice(n)
                                       for inner in _block_statements(s)
                                       for n in ast.walk(inner))
        for s in tree.body)


_BLOCKS = (ast.For, ast.AsyncFor, ast.While, ast.With, ast.AsyncWith, ast.If, *TRIES)
"""Statements whose blocks (not ``except`` handlers) run where they stand."""
_NOTICES = frozenset({"warn", "warning", "debug", "info", "error", "critical", "exception"})
"""What a library's top-level blocks call to say an optional import is missing
(``warnings.warn``, ``logger.warning``)."""


def _notice(call: ast.Call) -> bool:
    """True for a call that only reports something (``warnings.warn(...)``): no work."""
    return isinstance(call.func, ast.Attribute) and call.func.attr in _NOTICES


def _called(statement: ast.stmt) -> bool:
    """True for a statement that is a call (``print(total)``)."""
    return isinstance(statement, ast.Expr) and isinstance(statement.value, ast.Call)


def _block_statements(statement: ast.stmt) -> Iterator[ast.stmt]:
    """The statements of the blocks of ``statement``, at any depth of blocks (not inside
    functions, classes or ``except`` handlers)."""
    for field in ("body", "orelse", "finalbody"):
        for inner in getattr(statement, field, []):
            yield inner
            if isinstance(inner, _BLOCKS):
                yield from _block_statements(inner)


def importers_of(package: Package, module: PythonModule) -> dict[str, list[Import]]:
    """The imports of the package's other modules that load ``module``, by importer's path:
    by its bare name from its own folder (a script's neighbour), relatively, or by its
    dotted name (not another project's module of the same name: ``otherlib.utils``)."""
    folder, name = posixpath.split(module.path[:-3])
    dotted = {key for key, path in (installed_modules(package) or {}).items()
              if path == module.path} or {module.path[:-3].replace("/", ".")}
    parents = {key.rpartition(".")[0] for key in dotted}
    found: dict[str, list[Import]] = {}
    for other in package.modules:
        if other.path == module.path:
            continue
        here = posixpath.dirname(other.path)
        for imported in other.imports:
            if imported.level:
                base = posixpath.normpath(posixpath.join(here, *[".."] * (imported.level - 1)))
                target = posixpath.normpath(posixpath.join(
                    base, *imported.module.split("."))) if imported.module else base
                hit = target == module.path[:-3] or target == folder and name in imported.names
            else:
                hit = imported.module == name and here == folder or imported.module in dotted \
                    or imported.module in parents and name in imported.names
            if hit:
                found.setdefault(other.path, []).append(imported)
    return found


def runtime_code(package: Package) -> list[PythonModule]:
    """Installed code that runs outside tests: all of it except pytest plugins."""
    plugins = pytest_plugins(package)
    return [m for m in installed_code(package) if m.path not in plugins]


def all_python(package: Package) -> list[PythonModule]:
    """Every parsed Python file: the package's modules and its Python launch files."""
    return [*package.modules, *(f.python for f in package.launch_files if f.python)]


def test_code(package: Package) -> list[PythonModule]:
    """Test modules (:func:`~pkgtool.rules.test_modules.test_files`) and pytest plugins."""
    plugins, scripts = pytest_plugins(package), console_script_files(package)
    tests = test_files(package)
    return [m for m in package.modules
            if (m.path in tests and m.path not in scripts) or m.path in plugins]


def classify(top: str, declared_names: Iterable[str], context: Context = Context()
             ) -> tuple[str, tuple[str, ...]]:
    """The kind of a top-level import and the keys that provide it, for ``context``'s target.

    A workspace package whose Python package ``top`` is provides it too, and comes first: the
    workspace builds it from source, though rosdep (``python3-x-pip``) or the distribution
    (a released package of the same name) may also have one. A released metapackage
    (``perception``) holds no code: a module of its name is someone else's.
    """
    distro = context.distro
    released = is_released_package(top, distro) and not is_metapackage(top)
    provider = context.provider(top)
    source = (provider,) if provider else ()
    keys = keys_for_import(top, distro)
    if keys:
        also = (*ALTERNATIVE_KEYS.get(top, ()), *((top,) if released else ()))
        return "third-party", tuple(dict.fromkeys((*source, *keys, *also)))
    if top in ROS_MODULE_PACKAGES or released or looks_like_ros(top):
        return "ros", tuple(dict.fromkeys(
            (*source, *accepted_keys(top, package_for_ros_module(top)))))
    if provider:
        return "ros", source
    if top in declared_names:
        return "ros", (top,)
    return "unknown", _guessed_keys(top)


def source_path_module(package: Package, module: PythonModule, imported: Import
                       ) -> str | None:
    """The installed module of this package that an absolute import names through folders
    above it (``lecture10_demo.action_demo.action_demo.navigate_client`` for the installed
    ``action_demo.navigate_client``: a path of the source tree, which no install has), when
    the import's first name is no module anything provides."""
    parts = imported.module.split(".") if not imported.level and imported.module else []
    installed = (installed_modules(package) or {}) if len(parts) > 2 else {}
    roots = {name.split(".")[0] for name in installed}
    if not roots or parts[0] in roots or parts[0] in _stdlib(package.context.distro) or \
            parts[0] in local_modules(package, module) or \
            classify(parts[0], (), package.context)[0] != "unknown":
        return None
    return next((".".join(parts[start:]) for start in range(1, len(parts) - 1)
                 if parts[start] in roots and ".".join(parts[start:]) in installed), None)


def _guessed_keys(top: str) -> tuple[str, ...]:
    """The keys a module rosdep and ROS do not know might have: ``python3-x``, its ``-pip``
    variant, its own name."""
    guess = "python3-" + top.lower().replace("_", "-")
    return guess, guess + "-pip", top


@lru_cache(maxsize=8)
def _stdlib(distro: str) -> frozenset[str]:
    """Standard library names never needing a key: the target's, and (PYC010's case) any
    Python 3's."""
    return stdlib_modules(distro) | any_stdlib_module()


@per_package
def beside_the_scripts(package: Package) -> frozenset[str]:
    """Modules installed into ``lib/<package>``, the folder of the console scripts: those
    data_files copies there (and the packages of the folders it copies Python files into,
    ``lib/<package>/helpers/gait.py``), and the ``.py`` files of ``scripts=`` (into setup.cfg's
    ``install_scripts``, which SET009 wants there): Python puts a script's folder first on
    the path, so they import by their bare names."""
    copied = {path.split("/")[0].removesuffix(".py")  # a module, a package
              for path in copied_beside_the_scripts(package)}
    scripts = package.setup_py.scripts if package.setup_py else None
    return frozenset(copied) | {posixpath.basename(script)[:-3]
                                for script in scripts or () if script.endswith(".py")}


@per_package
def copied_beside_the_scripts(package: Package) -> frozenset[str]:
    """The Python files data_files copies into ``lib/<package>/``, as paths below it
    (``helpers/gait.py``)."""
    library = f"lib/{package.name}/"
    return frozenset(posixpath.normpath(target)[len(library):]
                     for target in installed_data(package) or ()
                     if posixpath.normpath(target).startswith(library) and target.endswith(".py"))


def local_modules(package: Package, module: PythonModule) -> frozenset[str]:
    """Top-level names an import in ``module`` finds in the package itself: its own modules,
    the modules next to ``module`` (not ``module`` itself when another provider has its name:
    ``from launch import ...`` in ``my_pkg/launch.py`` is ROS's ``launch``, Python 3's imports
    being absolute), and for test code those pytest puts on ``sys.path`` and those of the
    folders above the test's (``python3 -m pytest tests`` run in ``tool/`` imports
    ``tool/generator.py`` from ``tool/tests/test_generator.py``: the current folder; their
    modules and regular packages, not a folder of Python files a package of its name on
    ``sys.path`` comes before, as ROS's ``launch`` does before a ``launch/`` folder); for
    installed code, the modules installed beside the console scripts
    (:func:`beside_the_scripts`)."""
    own = posixpath.basename(module.path).removesuffix(".py")
    siblings = _siblings(package, module.path)
    if own in siblings and own not in own_modules(package) and \
            provided_elsewhere(own, package.context):
        siblings = siblings - {own}
    local = own_modules(package) | siblings | _own_top_package(package, module.path)
    if not is_test_code(package, module):
        return local | beside_the_scripts(package)
    folder, above = posixpath.dirname(module.path), set()
    while folder:
        folder = posixpath.dirname(folder)
        prefix = f"{folder}/" if folder else ""
        above.update(name for name in _layout(package.files).children.get(folder, ())
                     if package.has_file(f"{prefix}{name}.py") or
                     package.has_file(f"{prefix}{name}/__init__.py"))
    return local | pytest_path_modules(package) | above


def _own_top_package(package: Package, path: str) -> frozenset[str]:
    """The top Python package the file at ``path`` is part of (its folders upwards while they
    hold an ``__init__.py``): a vendored library importing itself by name
    (``vendor/lib/lib/blocks/__init__.py`` imports ``lib``) with its folder on ``sys.path``."""
    folder, top = posixpath.dirname(path), None
    while folder and package.has_file(f"{folder}/__init__.py"):
        folder, top = posixpath.dirname(folder), posixpath.basename(folder)
    return frozenset({top}) if top and folder else frozenset()  # the root's: own_modules'


@per_package
def _kept_needs(package: Package) -> dict[tuple[str, bool | None], tuple[Need, ...]]:
    """:func:`needs` by (module path, ``guarded``), filled as asked (DEP001-DEP006, LCH003 and
    the fixes ask about the same modules)."""
    return {}


def needs(package: Package, module: PythonModule, *, guarded: bool | None = False
          ) -> tuple[Need, ...]:
    """Absolute imports of ``module`` that need a key, the first import of each name only.

    ``guarded`` selects unguarded imports (False), guarded ones (True) or both (None). Every
    import of an own module that the package itself imports only guarded counts as guarded.
    ROS modules of a ROS 1 package are provided by their own name (:func:`_ros1_keys`).
    Worked out once per module of the package and ``guarded``.
    """
    kept = _kept_needs(package)
    key = (module.path, guarded)
    if key not in kept:
        kept[key] = tuple(_needs(package, module, guarded))
    return kept[key]


_ROS1_CLIENTS = frozenset({"rospy", "roslib"})
"""ROS 1's Python client library: a module importing it unguarded is ROS 1 code."""


def is_ros1_module(package: Package, module: PythonModule) -> bool:
    """True for a module of a ROS 2 package that imports ``rospy`` or ``roslib`` unguarded:
    ROS 1 code left in the package, which cannot run at all on ROS 2 (the import fails first;
    DEP004 says so): its other imports and its API use are not ROS 2's."""
    return package.manifest is not None and not package.manifest.is_ros1 and any(
        imported.top_level in _ROS1_CLIENTS and not imported.guarded
        for imported in module.imports)


def _needs(package: Package, module: PythonModule, guarded: bool | None) -> Iterator[Need]:
    skip = local_modules(package, module)
    stdlib = _stdlib(package.context.distro)
    names = declared(package, ANY)
    optional = module.path in optional_modules(package)
    ros1 = is_ros1_package(package)
    seen: set[str] = set()
    owner = python_package_of(package, module)
    on_path = path_modules(package, module)
    above = outside_edits(package).get(module.path)
    copies = vendored_edits(package).get(module.path)
    ros1_code = is_ros1_module(package, module)
    for imported in module.imports:
        top = imported.top_level
        if ros1_code and top not in ROS1_PACKAGES:
            continue  # ROS 1 code: only its ROS 1 imports are told (DEP004)
        is_guarded = imported.guarded or optional or _lazy_extra(package, module, imported)
        if (not top or (guarded is not None and is_guarded != guarded)
                or top in skip or (top in stdlib and not keys_for_import(top))
                or enclosing_package_import(package, owner, imported)
                or kept_project_import(package, owner, imported)
                or any(line < imported.span.line and top in names for line, names in on_path)):
            continue
        for member in _namespace_members(imported):
            shown = f"{top}.{member}" if member else top
            if shown in seen:
                continue
            seen.add(shown)
            joined = shown.replace(".", "_")
            kind, keys = classify(joined, names, package.context)
            if package.name in keys:  # `azure.iot` read as `azure_iot`, the package's own name
                keys = tuple(k for k in keys if k != package.name)
                guessed = tuple(k for k in _guessed_keys(joined) if k != package.name)
                kind, keys = (kind, keys) if keys else ("unknown", guessed)
            if ros1 and kind == "unknown" and top in ROS1_PACKAGES:  # rospy in a catkin package
                kind, keys = "ros", (top,)
            elif kind == "unknown" and _interface_kind(imported.module):
                kind, keys = "ros", (top,)  # `from x.msg import Y`: rosidl's package
            elif kind == "unknown" and above is not None and above < imported.span.line and \
                    not _holds_module(package, top):
                continue  # maybe a module of the checkout a `sys.path` edit above reaches
            elif kind != "ros" and copies is not None and copies < imported.span.line:
                continue  # maybe the copy of a library another package's folder holds
            if ros1 and kind == "ros":
                keys = _ros1_keys(top, keys)
            elif ros1:  # Melodic and older: Python 2 keys (`python-serial`) count too
                keys = (*keys, *(f"python-{k[8:]}" for k in keys if k.startswith("python3-")))
            yield Need(module, imported, shown, kind, keys)


def _lazy_extra(package: Package, module: PythonModule, imported: Import) -> bool:
    """True for an import inside a function of a distribution setup.py (or setup.cfg) lists
    in ``extras_require`` (not its ``test`` or ``dev`` extras): an optional feature's
    requirement, loaded only when the feature runs (``def to_html(): import jinja2`` with
    ``extras_require={'html': ['Jinja2']}``). Not in test code, nor in a function that
    always runs: one the module calls at its top level, a console script's function or an
    ``__init__``."""
    names, keys = extra_requirements(package)
    top = imported.top_level
    if not names or not (normalised_name(top) in names or
                         keys & set(keys_for_import(top, package.context.distro))):
        return False
    tree = parse_tree(module.path, package.texts.get(module.path, ""))
    if not isinstance(tree, ast.Module) or is_test_code(package, module):
        return False
    functions, called = _function_imports(tree)
    function = functions.get(imported.span.line)
    return function is not None and function != "__init__" and function not in called and \
        function not in _entry_functions(package)


def normalised_name(name: str) -> str:
    """A distribution or module name as PEP 503 compares them (lower case, ``-`` for any run
    of ``-``, ``_`` and ``.``)."""
    from packaging.utils import canonicalize_name  # only here: few packages list extras

    return canonicalize_name(name)


_REQUIREMENT_NAME = lazy_pattern(r"\s*([A-Za-z0-9][A-Za-z0-9._-]*)")
_NOT_FEATURES = frozenset({"test", "tests", "testing", "dev", "develop", "lint", "doc", "docs"})
"""Extras that hold what tests or development need, not an optional feature's requirements."""


@per_package
def extra_requirements(package: Package) -> tuple[frozenset[str], frozenset[str]]:
    """The distributions the optional features of ``extras_require`` need (setup.py's, else
    setup.cfg's ``[options.extras_require]``; not :data:`_NOT_FEATURES`), PEP 503-normalised,
    and the rosdep keys that install them (``opencv-python``: ``python3-opencv``)."""
    found: list[str] = []
    setup = package.setup_py
    value = setup.extras_require.value if setup is not None and setup.extras_require else None
    if isinstance(value, dict):
        for extra, requirements in value.items():
            if str(extra).lower() not in _NOT_FEATURES:
                found.extend([requirements] if isinstance(requirements, str) else
                             [r for r in requirements if isinstance(r, str)]
                             if isinstance(requirements, (list, tuple)) else [])
    cfg = package.setup_cfg
    if cfg is not None:
        found.extend(option.value for option in cfg.options
                     if option.section == "options.extras_require" and
                     option.key.lower() not in _NOT_FEATURES)
    matched = (_REQUIREMENT_NAME.match(line) for text in found for line in text.splitlines())
    distributions = {name.group(1) for name in matched if name}
    keys = {key for name in distributions
            for key in (suggested_key(name), suggested_key(name.lower()),
                        f"python3-{normalised_name(name)}", f"python3-{normalised_name(name)}-pip")
            if key}
    return frozenset(map(normalised_name, distributions)), frozenset(keys)


@per_package
def _entry_functions(package: Package) -> frozenset[str]:
    """The functions console scripts and other entry points run (``main``)."""
    setup = package.setup_py
    return frozenset(entry.attr.split(".")[0] for entry in (setup.entry_points or ())
                     if entry.attr) if setup is not None else frozenset()


@per_tree
def _function_imports(tree: ast.Module) -> tuple[dict[int, str], frozenset[str]]:
    """The import statements inside functions of ``tree`` (line -> the name of the outermost
    function around it, a method's own), and the names the module calls at its top level
    (``GREETING = _template()``, ``if __name__ == '__main__': main()``)."""
    lines: dict[int, str] = {}
    pending: list[tuple[ast.AST, str | None]] = [(tree, None)]
    while pending:
        node, function = pending.pop()
        if function is not None and isinstance(node, (ast.Import, ast.ImportFrom)):
            lines[node.lineno] = function
        if function is None and isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            function = node.name
        pending.extend((child, function) for child in ast.iter_child_nodes(node))
    called = {node.func.id for statement in tree.body
              if not isinstance(statement, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef))
              for node in ast.walk(statement)
              if isinstance(node, ast.Call) and isinstance(node.func, ast.Name)}
    return lines, frozenset(called)


def _holds_module(package: Package, name: str) -> bool:
    """True when some folder of the package holds a module or package ``name`` (an edit of
    ``sys.path`` that reaches above the package instead probably missed it)."""
    return any(posixpath.basename(path) == f"{name}.py" or path.endswith(f"{name}/__init__.py")
               and posixpath.basename(posixpath.dirname(path)) == name for path in package.files)


def _interface_kind(module: str | None) -> str | None:
    """``msg``, ``srv`` or ``action`` for ``x.msg``, ``x.srv`` and ``x.action``, the modules
    rosidl generates for an interface package ``x`` (whatever its name looks like); else
    None."""
    parts = (module or "").split(".")
    return parts[1] if len(parts) == 2 and parts[1] in KINDS else None


NAMESPACE_PACKAGES = {"google": "protobuf", "azure": "", "zope": "", "backports": "",
                      "jaraco": "", "sphinxcontrib": ""}
"""Top-level names that several distributions share as a namespace (``google.auth``,
``google.cloud.storage``, ``google.protobuf``), each with the one member its plain name stands
for in rosdep's data (``google``: protobuf's)."""


def _namespace_members(imported: Import) -> list[str | None]:
    """What ``imported`` needs: ``[None]`` for its top-level name; for a namespace package,
    each member it takes (``auth`` of ``import google.auth`` or ``from google import auth``,
    ``cloud.storage`` of ``from google.cloud import storage`` when rosdep's data knows that
    one; None for the member the plain name stands for), and nothing for the namespace alone
    (``import google``: whatever members the code reads are imported elsewhere)."""
    top = imported.top_level
    if top not in NAMESPACE_PACKAGES:
        return [None]
    parts = imported.module.split(".")[1:]
    names = [name for name in imported.names if name != "*"]
    if names:
        return [_member(top, [*parts, name]) for name in names]
    return [_member(top, parts)] if parts else []


def _member(top: str, parts: list[str]) -> str | None:
    """The member of the namespace ``top`` that ``parts`` (after it) reach: the longest start
    rosdep's data knows, else the first part; None when it is the one the plain name stands
    for."""
    if parts[0] == NAMESPACE_PACKAGES[top]:
        return None
    longest = next((parts[:n] for n in range(len(parts), 1, -1)
                    if keys_for_import("_".join([top, *parts[:n]]))), parts[:1])
    return ".".join(longest)


def _ros1_keys(top: str, keys: tuple[str, ...]) -> tuple[str, ...]:
    """The keys of a ROS import in a ROS 1 package: the module's own name counts too, and
    comes first where only ROS 2 moved the module to another package (``tf2_ros``, which
    ``tf2_ros_py`` provides in ROS 2 only)."""
    ordered = (top, *keys) if top in ROS_MODULE_PACKAGES else (*keys, top)
    return tuple(dict.fromkeys(ordered))


MAX_PLACES = 5
"""Other places of one mistake a message names (``related`` has them all)."""


def grouped(found: Iterable[Need], *, by_key: bool = False
            ) -> Iterator[tuple[Need, tuple[Need, ...]]]:
    """Needs of one top-level name together, first place first: one mistake, one hit.

    With ``by_key``, needs of one suggested key together instead (``matplotlib`` and
    ``mpl_toolkits``, both ``python3-matplotlib``): declaring that key provides each of them.
    """
    groups: dict[str, list[Need]] = {}
    for need in found:
        groups.setdefault(need.key if by_key else need.top, []).append(need)
    for first, *others in groups.values():
        yield first, tuple(others)


def also_imported(others: tuple[Need, ...], *, naming: bool = False) -> str:
    """``; also imported in `a.py:3`, ...`` for the other places of a need (or nothing);
    ``naming`` adds the module imported at each place (`` (`b`)``)."""
    if not others:
        return ""
    places = ", ".join(f"`{n.imported.span.path}:{n.imported.span.line}`"
                       + (f" (`{n.top}`)" if naming else "") for n in others[:MAX_PLACES])
    more = f" and {len(others) - MAX_PLACES} more" if len(others) > MAX_PLACES else ""
    return f"; also imported in {places}{more}"


def no_package_named(package: Package, name: str = "") -> str:
    """How a message says a name is no package pkgtool knows: of the target's release, or of
    the packages linted with this one (it sees no workspace beyond those); with ``name``, also
    the distributions that release it (``gazebo_ros``: humble), if any."""
    linted = " or of the packages linted with it" if len(package.context.workspace) > 1 else ""
    elsewhere = ", ".join(released_for(name)) if name else ""
    released = f" (it is released for {elsewhere})" if elsewhere else ""
    return f"no package of {package.context.distro}'s release{linted} has that name{released}"


def released_for(name: str) -> list[str]:
    """The distributions whose release has a package ``name``, oldest first."""
    return [distro for distro in DISTROS if is_released_package(name, distro)]


def misspelt_package(package: Package, need: Need) -> str | None:
    """The package a ROS import names with a typo (``sensors_msgs`` for ``sensor_msgs``): a
    name no package of any distribution's release, of the workspace or of package.xml has,
    nor a rosdep key, one edit away from exactly one of those (never a numbered sibling: a
    package built from another repository may well be called ``grbl_interfaces``); else
    None."""
    top, distro = need.top, package.context.distro
    workspace = package.context.workspace
    if need.kind != "ros" or "." in top or top in workspace or is_rosdep_key(top) or \
            any(is_released_package(top, other) for other in DISTROS):
        return None  # a package of another distribution is no typo
    names = frozenset((*workspace, *declared(package, ANY)))
    if top in names:
        return None
    meant = [close for close in close_names(top, distro, extra=names, limit=3)
             if not digits_differ(top, close) and typo_distance(top, close, 1) <= 1]
    return meant[0] if len(meant) == 1 and _has_imported(meant[0], need, distro) else None


def _has_imported(meant: str, need: Need, distro: str) -> bool:
    """False when ``need`` imports interfaces (``from x.action import Dock``) that the known
    package ``meant`` lacks: ``x`` is a package of its own (``action_msg`` beside
    ``action_msgs``), not a typo."""
    kind = _interface_kind(need.imported.module)
    if kind is None or not is_known_package(meant, distro):
        return True
    return all(interface_kind(meant, name, distro) == kind
               for name in need.imported.names if name != "*")


@per_package
def unmet_runtime_needs(package: Package) -> tuple[Need, ...]:
    """Needs of run-time code that no run-time key provides (none without a package.xml),
    worked out once per package (DEP001, DEP002 and the fixes read the same)."""
    return tuple(_unmet_runtime_needs(package))


def _unmet_runtime_needs(package: Package) -> Iterator[Need]:
    if package.manifest is None:
        return
    runtime = declared(package, RUNTIME)
    for module in runtime_code(package):
        for need in needs(package, module):
            if not any(k in runtime for k in need.keys):
                yield need


def misnamed(package: Package, need: Need) -> str | None:
    """Why a declared name does not provide ``need``, if one looks like it should.

    ``python-opencv`` declared for python3-opencv; ``tf2_ros`` (the C++ package) declared for
    ``import tf2_ros``, which ``tf2_ros_py`` provides.
    """
    names = declared(package, ANY, bringing=False)
    wrong = next((name for name in names if suggested_key(name) == need.key), None)
    if wrong:
        return f"`{wrong}` is declared, but the rosdep key is `{need.key}`"
    if need.top in names and need.top not in need.keys:
        return (f"`{need.top}` is declared, but that package does not provide the Python "
                f"module: `{need.key}` does")
    return None


def launch_keys(package: Package, path: str) -> dict[str, Dependency]:
    """Keys a launch file may use: run-time ones, and test ones for launch files of tests."""
    return declared(package, RUNTIME | TEST if is_test_launch(path) else RUNTIME)


def is_test_launch(path: str) -> bool:
    """True for a launch file of the package's tests (under ``test/`` or ``tests/``)."""
    return path.split("/", 1)[0] in ("test", "tests")
