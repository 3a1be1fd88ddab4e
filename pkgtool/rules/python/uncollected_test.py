"""PYC012: a file under test/ defines tests that pytest never collects."""

from __future__ import annotations

import ast
import posixpath
import re
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.model.installed import is_ament_python
from pkgtool.model.package import Package
from pkgtool.model.pytest_config import PytestConfig, pytest_config
from pkgtool.model.python_visitor import parse_tree
from pkgtool.model.span import Span
from pkgtool.rules.pytest_fixtures import package_fixtures
from pkgtool.rules.registry import rule
from pkgtool.rules.test_modules import first_test, matches, why_not_collected


def _read_by_other_tests(package: Package, path: str) -> bool:
    """True when another test file names this file, or a folder holding it, in a string.

    Such files are test data: another test runs them itself (pytester, launch_testing).
    """
    parts = path.split("/")
    words = {*parts[1:-1], parts[-1], parts[-1][:-3]}
    found = re.compile("|".join(rf"['\"/]{re.escape(w)}['\"/.]" for w in words))
    return any(other != path and other.split("/")[0] == parts[0] and found.search(text)
               for other, text in package.texts.items() if other.endswith(".py"))


def _explicit_arguments(package: Package, config: PytestConfig) -> bool:
    """True when ``addopts`` names a file or folder: pytest then collects just what it names."""
    return any(not a.startswith("-") and (package.has_file(a.rstrip("/")) or any(
        f.startswith(a.rstrip("/") + "/") for f in package.files)) for a in config.get("addopts"))


@rule("PYC012", "uncollected-test", Severity.WARNING,
      fix="Name the file `test_<name>.py`, or change the pytest setting that leaves it out")
def uncollected_test(package: Package) -> Iterator[Hit]:
    """A file under `test/` defines tests that pytest never collects.

    ## What it does
    Finds Python files under `test/` or `tests/` of an ament_python package that define a
    test (a top-level `test*` function, or a `Test*` class or `unittest.TestCase` with
    `test*` methods) that `colcon test` never runs: pytest, started in the package folder
    without arguments, does not collect the file because its name matches no `python_files`
    pattern (`test_*.py`, `*_test.py` by default), `testpaths` leaves it out, or a
    `norecursedirs` pattern skips its folder. These settings are read from the file pytest
    uses: `pytest.ini`, `pyproject.toml` (`[tool.pytest.ini_options]`), `tox.ini` or
    `setup.cfg` (`[tool:pytest]`); `python_functions` and `python_classes` are honoured too.
    A configuration that does not parse, or `addopts` naming paths, leaves the rule silent,
    and so does a file that another test names in a string (its name, or a folder holding
    it): test data that the other test runs itself (pytester, launch_testing). In the files
    pytest does collect, also reports a test class defining `__init__` (pytest skips it with a
    mere warning; not a `unittest.TestCase`, which pytest runs anyway) and a top-level
    function that pytest does not collect although it is written as a test, named like one
    (`talker_test`, `Test_talker`) or taking only fixtures (`def talker_publishes(ros):`, with
    `ros` a fixture of a conftest.py, or pytest's own `tmp_path`), that asserts, has no
    decorator, and that neither its file nor another file of the package names (a helper
    other tests import).

    ## Why is this bad?
    The tests never run, and `colcon test` reports success: the checks they were written
    for are silently lost.

    ## Example
    ```text
    test/speed_limits.py    # def test_limits(): ...
    ```

    ## Use instead
    ```text
    test/test_speed_limits.py
    ```
    """
    config = pytest_config(package)
    if config is None or not is_ament_python(package) or _explicit_arguments(package, config):
        return
    for module in package.modules:
        path = module.path
        if path.split("/")[0] not in ("test", "tests") or module.syntax_error or \
                posixpath.basename(path) in ("conftest.py", "__init__.py"):
            continue
        reason = why_not_collected(package, path, config)
        tree = parse_tree(path, package.texts[path]) if reason else None
        test = first_test(tree, config) if isinstance(tree, ast.Module) else None
        if reason and test is not None and not _read_by_other_tests(package, path):
            yield Hit(Span(path, test.lineno, test.col_offset + 1),
                      f"pytest does not collect `{path}`, so its tests never run: {reason}")
        elif not reason and not _read_by_other_tests(package, path):
            tree = parse_tree(path, package.texts[path])
            if isinstance(tree, ast.Module):
                yield from _uncollected_parts(package, path, tree, config)


def _asserts(node: ast.AST) -> bool:
    return any(isinstance(n, ast.Assert) for n in ast.walk(node))


def _named_elsewhere(package: Package, path: str, name: str) -> bool:
    """True when another Python file of the package names ``name`` (imports the helper)."""
    word = re.compile(rf"\b{re.escape(name)}\b")
    return any(other != path and other.endswith(".py") and word.search(text)
               for other, text in package.texts.items())


def _misnamed(name: str, functions: tuple[str, ...]) -> bool:
    """True for a name written as a test's that pytest does not collect: ``talker_test``,
    ``Test_talker`` (the default prefix is ``test``, lower case)."""
    return not matches(name, functions) and (
        name.endswith("_test") or name.lower().startswith("test"))


def _without_test(name: str, functions: tuple[str, ...]) -> str:
    """``name`` without the misplaced ``test`` of a misnamed test (``talker_test``)."""
    return name.lower().replace("test", "").strip("_") if _misnamed(name, functions) else name


def _takes_fixtures(package: Package, function: ast.FunctionDef) -> bool:
    """True for a function whose parameters (one at least) are all fixtures the package's
    tests may take: written to be run by pytest (``talker_publishes(ros)``)."""
    arguments = function.args
    names = [a.arg for a in (*arguments.posonlyargs, *arguments.args, *arguments.kwonlyargs)]
    return bool(names) and arguments.vararg is None and arguments.kwarg is None and \
        set(names) <= package_fixtures(package)


def _uncollected_parts(package: Package, path: str, tree: ast.Module, config: PytestConfig
                       ) -> Iterator[Hit]:
    """In a file pytest collects: plain test classes it skips for their ``__init__``, and
    functions written as tests (misnamed, asserting, used nowhere) under a name it skips."""
    functions, classes = config.get("python_functions"), config.get("python_classes")
    used = {n.id for n in nodes_of_class(tree, ast.Name)}  # type: ignore[attr-defined]
    for node in tree.body:
        plain = isinstance(node, ast.ClassDef) and all(
            isinstance(b, ast.Name) and b.id == "object" for b in node.bases)
        if plain and matches(node.name, classes) and any(  # type: ignore[attr-defined]
                isinstance(s, ast.FunctionDef) and s.name == "__init__"
                for s in node.body) and \
                any(isinstance(s, ast.FunctionDef) and matches(s.name, functions)
                    for s in node.body):  # type: ignore[attr-defined]
            yield Hit(Span(path, node.lineno, node.col_offset + 1),
                      f"`{node.name}` defines `__init__`: pytest does not collect a test class "
                      "with a constructor (only a PytestCollectionWarning says so), its tests "
                      "never run", "Set up in `setup_method(self)` or a fixture, not `__init__`")
        elif isinstance(node, ast.FunctionDef) and (
                _misnamed(node.name, functions) or _takes_fixtures(package, node)) and \
                not matches(node.name, functions) and \
                not node.decorator_list and node.name not in used and _asserts(node) and \
                not _named_elsewhere(package, path, node.name):
            shown = " or ".join(f"`{p}`" for p in functions)
            yield Hit(Span(path, node.lineno, node.col_offset + 1),
                      f"`{node.name}` asserts like a test, but its name does not match {shown} "
                      "(pytest's `python_functions`) and nothing calls it: it never runs",
                      f"Name it `test_{_without_test(node.name, functions)}`")
