"""pytest fixtures in a package's test code: which functions are fixtures, which names a test
may take as parameters."""

from __future__ import annotations

import ast
import posixpath

from pkgtool.model.memo import per_package
from pkgtool.model.package import Package
from pkgtool.rules.syntax_trees import Index, index_of, python_files
from pkgtool.rules.test_modules import test_files

_FIXTURE = frozenset({"pytest.fixture", "pytest.yield_fixture"})
BUILTIN_FIXTURES = frozenset({
    "cache", "capfd", "capfdbinary", "caplog", "capsys", "capsysbinary", "doctest_namespace",
    "monkeypatch", "pytestconfig", "pytester", "record_property", "record_testsuite_property",
    "record_xml_attribute", "recwarn", "request", "testdir", "tmp_path", "tmp_path_factory",
    "tmpdir", "tmpdir_factory"})
"""The fixtures pytest itself provides to every test."""


def is_fixture(function: ast.AST, index: Index) -> bool:
    """True for a function (``async`` too) decorated with ``pytest.fixture`` (with or without
    arguments), or the older ``pytest.yield_fixture``."""
    return isinstance(function, (ast.FunctionDef, ast.AsyncFunctionDef)) and any(
        index.qualified(d.func if isinstance(d, ast.Call) else d) in _FIXTURE
        for d in function.decorator_list if isinstance(d, (ast.Name, ast.Attribute, ast.Call)))


def fixture_name(function: ast.FunctionDef | ast.AsyncFunctionDef) -> str:
    """The name a fixture is asked for by: its ``name=``, else the function's."""
    for decorator in function.decorator_list:
        for keyword in decorator.keywords if isinstance(decorator, ast.Call) else ():
            if keyword.arg == "name" and isinstance(keyword.value, ast.Constant) and \
                    isinstance(keyword.value.value, str):
                return keyword.value.value
    return function.name


@per_package
def package_fixtures(package: Package) -> frozenset[str]:
    """The fixtures the package's tests may take: pytest's own, and those its test modules and
    ``conftest.py`` files define."""
    tests = test_files(package)
    found = set(BUILTIN_FIXTURES)
    for path, _, tree in python_files(package, ("fixture",)):
        if path in tests or posixpath.basename(path) == "conftest.py":
            index = index_of(tree)
            found.update(fixture_name(f) for f in tree.body  # type: ignore[arg-type]
                         if is_fixture(f, index))
    return frozenset(found)
