"""What ``colcon build`` installs from an ament_python package, as far as setup.py tells.

Module names map to their source files (setuptools' ``build_py`` rules: every ``*.py`` directly
in each listed package's folder, ``package_dir`` mapping, ``py_modules``), and data_files
destinations map to their sources. Every function returns None when setup.py leaves the answer
to code the evaluator could not compute.
"""

from __future__ import annotations

import posixpath
from fnmatch import fnmatchcase

from pkgtool.lazy_regex import lazy_pattern
from pkgtool.model.cmake_install import installed_sources
from pkgtool.model.cmake_text import with_included
from pkgtool.model.launch import python_folders
from pkgtool.model.memo import per_package
from pkgtool.model.package import Package
from pkgtool.model.setup_py import SetupPy

_CFG_KEYWORDS = {
    "name": ("metadata", "name"), "version": ("metadata", "version"),
    "license": ("metadata", "license"), "maintainer": ("metadata", "maintainer"),
    "maintainer_email": ("metadata", "maintainer_email"),
    "packages": ("options", "packages"), "package_dir": ("options", "package_dir"),
    "py_modules": ("options", "py_modules"), "tests_require": ("options", "tests_require"),
    "extras_require": ("options.extras_require", None),
    "entry_points": ("options.entry_points", None), "data_files": ("options.data_files", None),
}
"""Where setup.cfg's declarative configuration can give each setup() keyword."""
DATA_FOLDERS = frozenset({"launch", "config", "params", "param", "resource", "test", "tests",
                          "models", "meshes", "urdf", "worlds", "maps", "rviz", "msg", "srv",
                          "action", "doc", "docs"})
"""Folders of a ROS package that hold data, launch files or tests, never its Python code."""
_INSTALL_KEYWORDS = frozenset({"packages", "package_dir", "py_modules", "data_files"})
"""Keywords whose effect custom ``cmdclass`` commands can change."""
_MODULE_COMMANDS = frozenset({"build", "build_py", "build_ext", "install_lib", "egg_info"})
"""setuptools commands whose replacement may build or install other modules than setup()
names."""
_SCRIPT_COMMANDS = frozenset({"install", "develop"})
"""Commands whose replacement usually moves the console scripts only, unless it runs
programs or writes files (:attr:`~pkgtool.model.setup_py.SetupPy.acting_commands`)."""
PROJECT_FILES = frozenset({"setup.py", "pyproject.toml"})
"""Files that make their folder a Python project of its own."""


def is_ament_python(package: Package) -> bool:
    """True for a package colcon builds with setup.py (ament_python, or no CMakeLists.txt)."""
    manifest = package.manifest
    if manifest is not None and manifest.build_type is not None:
        return manifest.build_type.value == "ament_python"
    return not package.has_file("CMakeLists.txt")


@per_package
def separate_projects(package: Package) -> frozenset[str]:
    """Folders below the package root with their own setup.py or pyproject.toml.

    Each is a Python project of its own (a pip-installable API, a vendored tool): colcon
    installs none of its files as this package's code, whatever the package's build type.
    Not a folder the package's setup.py installs as one of its Python packages (a stray
    setup.py left inside ``my_pkg/``): its modules are installed all the same.
    """
    setup = package.setup_py
    installed = {package_folder(name, setup.package_dir or {}) for name in (
        setup.packages.names if setup and setup.packages else ())}
    return frozenset(folder for folder, _, name in (p.rpartition("/") for p in package.files)
                     if folder and name in PROJECT_FILES and folder not in installed)


def in_separate_project(package: Package, path: str) -> bool:
    """True for a file inside one of the package's :func:`separate_projects`."""
    return any(path.startswith(folder + "/") for folder in separate_projects(package))


def keyword_known(package: Package, keyword: str) -> bool:
    """True when setup.py's value for ``keyword`` is known: evaluated, or certainly absent."""
    setup = package.setup_py
    if setup is None or setup.setup_span is None:
        return False
    if setup.is_unresolved(keyword) or setup.is_unresolved("**"):
        return False
    if keyword in _INSTALL_KEYWORDS and "cmdclass" in (*setup.keywords, *dict(setup.unresolved)) \
            and not _commands_keep(keyword, setup):
        return False  # custom build or install commands may install anything
    if keyword in setup.keywords or package.setup_cfg is None:
        return True
    section, option = _CFG_KEYWORDS.get(keyword, (None, None))
    cfg = package.setup_cfg
    if option is None:
        return not any(o.section == section for o in cfg.options)
    return cfg.get(section, option) is None


def _commands_keep(keyword: str, setup: SetupPy) -> bool:
    """True when the custom commands of ``cmdclass`` (a dict display) leave what ``keyword``
    installs as setup() says: for the modules (``packages``, ``package_dir``, ``py_modules``),
    no command that builds or installs them is replaced, and an ``install`` or ``develop``
    replaced only changes options or prints (one running ``protoc`` first makes modules);
    ``data_files`` only when no command is replaced."""
    if setup.commands is None:
        return False
    if keyword == "data_files":
        return not setup.commands
    return not set(setup.commands) & _MODULE_COMMANDS and \
        not set(setup.acting_commands) & _SCRIPT_COMMANDS


def found_top_level(package: Package) -> frozenset[str]:
    """Top-level packages ``find_packages()``/``find_namespace_packages()`` install, if known."""
    spec = package.setup_py.packages if package.setup_py else None
    if spec is None or spec.kind == "list" or not keyword_known(package, "packages"):
        return frozenset()
    return frozenset(name.split(".")[0] for name in spec.names)


def package_folder(package_name: str, package_dir: dict[str, str]) -> str:
    """The folder setuptools reads a dotted package from (``build_py.get_package_dir``)."""
    path = package_name.split(".") if package_name else []
    tail: list[str] = []
    while path:
        mapped = package_dir.get(".".join(path))
        if mapped is not None:
            return posixpath.normpath(posixpath.join(mapped, *tail)) if tail or mapped else ""
        tail.insert(0, path.pop())
    root = package_dir.get("", "")
    joined = posixpath.join(root, *tail) if tail else root
    return posixpath.normpath(joined) if joined else ""


@per_package
def installed_modules(package: Package) -> dict[str, str] | None:
    """Every dotted module name setup.py installs, mapped to its package-relative file; None
    for a package ament builds with CMake, whose setup.py colcon never runs (one left over
    from an ament_python start), and when not known."""
    setup = package.setup_py
    cmake = not is_ament_python(package) and not (package.manifest and package.manifest.is_ros1)
    if setup is None or cmake or not all(
            keyword_known(package, k) for k in ("packages", "py_modules", "package_dir")):
        return None
    if setup.packages is None and setup.py_modules is None:
        return None  # setuptools' automatic discovery decides; not simulated
    package_dir = setup.package_dir or {}
    by_folder: dict[str, list[str]] = {}
    for file in package.files:
        if file.endswith(".py") and not posixpath.basename(file).startswith("."):
            by_folder.setdefault(posixpath.dirname(file), []).append(file)  # glob's `*.py`
    modules: dict[str, str] = {}
    for name in setup.packages.names if setup.packages else ():
        # 'src/pkg' (also 'src/pkg/') installs to src/pkg: `src.pkg`, a namespace package
        dotted = posixpath.normpath(name).replace("/", ".") if "/" in name else name
        for file in by_folder.get(package_folder(name, package_dir), ()):
            stem = posixpath.basename(file)[:-3]
            if file != "setup.py":
                modules[dotted if stem == "__init__" else f"{dotted}.{stem}"] = file
    for name in setup.py_modules or ():
        parent, _, leaf = name.rpartition(".")
        file = posixpath.join(package_folder(parent, package_dir), leaf + ".py")
        if package.has_file(file):
            modules[name] = file
    return modules


@per_package
def installed_files(package: Package) -> frozenset[str]:
    """Python files colcon installs as modules, tests included: those setup.py installs when
    that is known (with the scripts data_files copies into ``lib/<package>``, which ``ros2
    run`` starts, and the ``.py`` files of ``scripts=``), else files inside Python package
    folders other than data folders (CMake installs ``launch/``, ``config/``, ... to
    ``share/``, whatever ``__init__.py`` they hold), and of a CMake package only those its
    CMakeLists.txt installs when that is known (:func:`cmake_installed`), with the Python
    files it names (``install(PROGRAMS scripts/node.py ...)``: what ``ros2 run`` starts). A
    setup.py and the files of a
    :func:`separate_projects` project never are, nor what the setup.py of a CMake package
    names (colcon never runs it); when what CMake installs is not known, nor the folders of
    the scripts it runs while building (:func:`build_time_folders`)."""
    installed = installed_modules(package) if is_ament_python(package) else None
    if installed is not None:
        scripts = f"lib/{package.name}/"
        files = frozenset(installed.values()) | {
            source for target, source in (installed_data(package) or {}).items()
            if target.startswith(scripts) and source.endswith(".py")} | {  # `ros2 run` starts
            posixpath.normpath(script) for script in (package.setup_py.scripts or ())
            if script.endswith(".py") and package.has_file(posixpath.normpath(script))}
    else:
        packages = python_folders(package.files)
        data = DATA_FOLDERS - {package.name}
        files = frozenset(m.path for m in package.modules if posixpath.dirname(m.path) in packages
                          and posixpath.dirname(m.path)
                          and m.path.split("/", 1)[0] not in data)
        sources = cmake_installed(package)
        if sources is not None:
            named = {m.path for m in package.modules if m.path in sources}  # PROGRAMS x.py
            files = frozenset(f for f in files if any(
                s == "." or f == s or f.startswith(s + "/") for s in sources)) | named
        elif not is_ament_python(package):
            tools = build_time_folders(package)
            files = frozenset(f for f in files if posixpath.dirname(f) not in tools)
    return frozenset(f for f in files if posixpath.basename(f) != "setup.py"
                     and not posixpath.basename(f).startswith(".")  # setuptools globs `*.py`
                     and not in_separate_project(package, f))


_RUN_BY_PYTHON = lazy_pattern(r"\$\{(?:PYTHON|Python3?|PYTHON3)_EXECUTABLE\}\s+\"?"
                              r"(?:\$\{(?:CMAKE_CURRENT_SOURCE_DIR|PROJECT_SOURCE_DIR|"
                              r"CMAKE_CURRENT_LIST_DIR)\}/)?([\w./-]+)\.py\b")
"""A Python script a CMake file runs while building (``${PYTHON_EXECUTABLE}
${CMAKE_CURRENT_SOURCE_DIR}/scripts/gen.py``)."""


@per_package
def build_time_folders(package: Package) -> frozenset[str]:
    """The package folders holding Python scripts its CMake files run at build time (code
    generators): tools of the build, not installed code."""
    texts = [text for path, text in package.texts.items()
             if path == "CMakeLists.txt" or path.endswith(".cmake")]
    return frozenset(posixpath.dirname(posixpath.normpath(match))
                     for text in texts for match in _RUN_BY_PYTHON.findall(text)
                     if "/" in match and not match.startswith(".."))


@per_package
def cmake_text(package: Package) -> str | None:
    """The package's CMakeLists.txt followed by the CMake files it includes
    (:func:`~pkgtool.model.cmake_text.with_included`), read once per package (several rules
    ask); None without one."""
    cmake = package.texts.get("CMakeLists.txt")
    return None if cmake is None else with_included(cmake, package.texts.get)


@per_package
def cmake_installed(package: Package) -> frozenset[str] | None:
    """The files and folders the CMakeLists.txt of a package colcon builds with CMake installs
    (:func:`~pkgtool.model.cmake_install.installed_sources`), None when not known: a Python
    folder it never installs (a build-time generator, a test helper the tests put on
    ``PYTHONPATH``) is no installed code."""
    text = cmake_text(package)
    if text is None or is_ament_python(package):
        return None
    return installed_sources(text, package.files)


@per_package
def installed_data(package: Package) -> dict[str, str] | None:
    """data_files: installed path (relative to the install prefix) -> source file."""
    setup = package.setup_py
    if setup is None or not keyword_known(package, "data_files"):
        return None
    installed: dict[str, str] = {}
    for entry in setup.data_files or ():
        if entry.sources_is_text:
            continue
        for source in entry.sources:
            for match in source.matches:
                if package.has_file(match):
                    target = posixpath.join(entry.destination, posixpath.basename(match))
                    installed[posixpath.normpath(target)] = match
    return installed


def why_not_installed(package: Package, module: str) -> tuple[str, bool]:
    """Why ``module`` is not among the installed modules, and whether its source file exists."""
    setup = package.setup_py
    assert setup is not None
    package_dir = setup.package_dir or {}
    parent, _, leaf = module.rpartition(".")
    candidates = [posixpath.join(package_folder(module, package_dir), "__init__.py"),
                  posixpath.join(package_folder(parent, package_dir), leaf + ".py")]
    source = next((c for c in candidates if package.has_file(c)), None)
    if source is None:
        near = _same_file_elsewhere(package, module)
        hint = f" (`{near}` exists, but `package_dir` does not point there)" if near else ""
        return f"there is no `{candidates[1]}` or `{candidates[0]}`{hint}", False
    owner = module if source.endswith("/__init__.py") else parent
    if not owner:
        return f"`{leaf}.py` is a top-level module, and `py_modules` does not list `{leaf}`", True
    return _why_package_missing(package, owner), True


def _same_file_elsewhere(package: Package, module: str) -> str | None:
    tail = module.replace(".", "/")
    return next((f for f in package.files
                 if f.endswith((f"/{tail}.py", f"/{tail}/__init__.py"))), None)


def _why_package_missing(package: Package, owner: str) -> str:
    spec = package.setup_py.packages if package.setup_py else None
    if spec is None:
        return f"setup.py installs no packages, so `{owner}` is left out"
    if spec.kind == "list":
        shown = ", ".join(f"'{n}'" for n in spec.names)
        parents = [n for n in spec.names if owner.startswith(n + ".")]
        if parents:
            return (f"`packages=[{shown}]` drops subpackages: `{owner}` is not listed "
                    "(it only works with `--symlink-install`)")
        return f"`packages=[{shown}]` does not list `{owner}`"
    finder = f"{spec.kind}()"
    root = "" if posixpath.normpath(spec.where) == "." else posixpath.normpath(spec.where)
    parts = owner.split(".")
    if spec.kind == "find_packages":
        for depth in range(1, len(parts) + 1):
            init = posixpath.join(root, *parts[:depth], "__init__.py")
            if not package.has_file(init):
                return f"`{init}` is missing, so `{finder}` skips `{owner}`"
    excluded = [p for p in spec.exclude if fnmatchcase(owner, p)]
    if excluded:
        return f"`{finder}` excludes `{owner}` with the pattern `{excluded[0]}`"
    if not any(fnmatchcase(owner, p) for p in spec.include):
        return f"`{finder}` includes only {', '.join(f'`{p}`' for p in spec.include)}"
    return f"`{finder}` with `where='{spec.where}'` does not find `{owner}`"
