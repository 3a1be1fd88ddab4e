"""Which Python files are test code: what pytest collects, and the package's test modules."""

from __future__ import annotations

import ast
import posixpath
import re
from collections.abc import Iterator
from fnmatch import fnmatch

from pkgtool.model.ast_nodes import TRIES, block_statements
from pkgtool.model.installed import cmake_text, installed_files
from pkgtool.model.manifest import CMAKE_BUILD_TYPES
from pkgtool.model.memo import per_package
from pkgtool.model.modules import PythonModule
from pkgtool.model.package import Package, is_test_material
from pkgtool.model.pytest_config import PytestConfig, pytest_config
from pkgtool.model.python_visitor import parse_tree

_GLOB = frozenset("*?[")


def matches(name: str, patterns: tuple[str, ...]) -> bool:
    """pytest's name test: a glob matches whole, anything else is a prefix."""
    return any(fnmatch(name, p) if _GLOB & set(p) else name.startswith(p) for p in patterns)


def first_test(tree: ast.Module, config: PytestConfig) -> ast.AST | None:
    """The first module-level test function, or class holding test methods, pytest would run
    (also one defined under a module-level ``if``, ``try`` or ``with``: ``if os.name !=
    'nt':``)."""
    functions, classes = config.get("python_functions"), config.get("python_classes")
    for node in block_statements(tree.body, (ast.If, ast.With, ast.AsyncWith, *TRIES)):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) and \
                matches(node.name, functions):
            return node
        if isinstance(node, ast.ClassDef):
            unittest = any((b.attr if isinstance(b, ast.Attribute) else getattr(b, "id", ""))
                           == "TestCase" for b in node.bases)
            methods = ("test",) if unittest else functions
            if (unittest or matches(node.name, classes)) and any(
                    isinstance(m, (ast.FunctionDef, ast.AsyncFunctionDef)) and
                    matches(m.name, methods) for m in node.body):
                return node
    return None


def why_not_collected(package: Package, path: str, config: PytestConfig) -> str | None:
    """Why pytest, run in the package folder with no arguments, skips ``path``; None if not."""
    roots = [r for t in config.get("testpaths") for r in _expand(package, t)]
    if config.get("testpaths") and not roots:
        return None  # testpaths names nothing that exists: pytest falls back to the folder
    root = next((r for r in roots if r in ("", path) or path.startswith(r + "/")), None)
    if roots and root is None:
        listed = " ".join(config.get("testpaths"))
        return f"`testpaths = {listed}` in {config.path} does not include it"
    if path == root:
        return None  # named explicitly: collected whatever its name
    folders = posixpath.dirname(path[len(root) + 1:] if root else path)
    for folder in folders.split("/") if folders else ():
        pattern = next((p for p in config.get("norecursedirs") if fnmatch(folder, p)), None)
        if pattern:
            return f"`norecursedirs` pattern `{pattern}`{config.where('norecursedirs')} " \
                   f"skips the folder `{folder}`"
    patterns = config.get("python_files")
    if not any(fnmatch(posixpath.basename(path), p) for p in patterns):
        shown = ", ".join(f"`{p}`" for p in patterns)
        return f"its name matches none of {shown}{config.where('python_files')}"
    return None


def _expand(package: Package, entry: str) -> list[str]:
    """Package files and folders a ``testpaths`` entry (a glob) names."""
    entry = posixpath.normpath(entry)
    if entry == ".":
        return [""]
    folders = {posixpath.dirname(f) for f in package.files} | set(package.files)
    parents = {"/".join(p.split("/")[:n]) for p in folders for n in range(1, p.count("/") + 2)}
    return sorted(p for p in parents if fnmatch(p, entry))


@per_package
def test_files(package: Package) -> frozenset[str]:
    """Paths of the package's test modules.

    A module under ``test/`` or ``tests/``, a ``conftest.py`` and a module named like a test
    (``test_*.py``, ``*_test.py``) are, except such a module that colcon installs as part of a
    Python package (outside any ``test``/``tests`` folder): code the package ships (a base
    class for other packages' tests, imported at run time), unless pytest collects it and it
    defines a test (a test shipped by mistake); nor is such a module outside test folders of
    a CMake package that its CMake files never name (a demo script ctest never runs).
    """
    installed = installed_files(package)
    config = pytest_config(package) or PytestConfig()
    return frozenset(m.path for m in package.modules if m.is_test and not (
        m.path in installed and _shipped_code(package, m, config)) and
        not _cmake_script(package, m.path))


def _cmake_script(package: Package, path: str) -> bool:
    """True for a module named like a test, outside test folders, of a package CMake builds
    whose CMake files never name it, or install it as a program (``install(PROGRAMS
    scripts/jtc_test.py ...)``: a tool ``ros2 run`` starts): ``colcon test`` runs ctest
    there, which runs only the tests CMakeLists.txt registers (``ament_add_pytest_test``),
    never pytest's own search."""
    build_type = package.manifest.build_type if package.manifest else None
    if build_type is None or build_type.value not in CMAKE_BUILD_TYPES or \
            is_test_material(path) or posixpath.basename(path) == "conftest.py":
        return False
    cmake = cmake_text(package) or ""
    name = posixpath.basename(path)
    return name not in cmake or re.search(
        rf"(?i)\binstall\s*\(\s*PROGRAMS\b[^)]*\b{re.escape(name)}\b", cmake) is not None


def _shipped_code(package: Package, module: PythonModule, config: PytestConfig) -> bool:
    """True for an installed module named like a test that is no test pytest runs."""
    path = module.path
    if posixpath.basename(path) == "conftest.py" or is_test_material(path):
        return False
    if why_not_collected(package, path, config) is not None:
        return True
    tree = parse_tree(path, package.texts[path]) if path in package.texts else None
    return not isinstance(tree, ast.Module) or first_test(tree, config) is None


def test_trees(package: Package) -> Iterator[tuple[str, ast.Module]]:
    """(path, tree) of each of the package's :func:`test_files` that parses, in path order."""
    for path in sorted(test_files(package)):
        tree = parse_tree(path, package.texts[path]) if path in package.texts else None
        if isinstance(tree, ast.Module):
            yield path, tree


def is_test_code(package: Package, module: PythonModule) -> bool:
    """True for one of the package's :func:`test_files`."""
    return module.path in test_files(package)
