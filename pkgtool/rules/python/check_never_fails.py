"""PYC052: an ``assert`` or a test whose check can never fail."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.model.package import Package, is_test_material
from pkgtool.model.pytest_config import PytestConfig, pytest_config
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import python_files
from pkgtool.rules.scopes import scope_walk
from pkgtool.rules.test_modules import matches

_CHECKS = (ast.Compare, ast.BoolOp)
"""What a test returns when it meant to assert it."""


def _tuple_asserts(path: str, tree: ast.Module) -> Iterator[Hit]:
    for node in nodes_of_class(tree, ast.Assert):
        test = node.test  # type: ignore[attr-defined]
        if isinstance(test, ast.Tuple) and test.elts:
            shown = ast.unparse(test.elts[0])
            yield Hit(Span(path, node.lineno, node.col_offset + 1),
                      f"`assert ({ast.unparse(test)[1:-1]})` asserts a tuple, which is never "
                      "empty and so always true: the check never fails",
                      f"Drop the parentheses: `assert {shown}, <message>`")


def _collectable(body: list[ast.stmt]) -> Iterator[ast.FunctionDef]:
    """The functions pytest may collect: at module level and in classes (nested ones too),
    never those defined inside a function (a helper the test calls or hands on)."""
    for statement in body:
        if isinstance(statement, ast.FunctionDef):
            yield statement
        elif isinstance(statement, ast.ClassDef):
            yield from _collectable(statement.body)


def _returned_checks(path: str, tree: ast.Module, config: PytestConfig) -> Iterator[Hit]:
    """``return <comparison>`` in a test function's own body (not in a function nested in it:
    a predicate the test passes on; nor in a function defined inside another)."""
    functions = config.get("python_functions")
    for node in _collectable(tree.body):
        if not matches(node.name, functions):
            continue
        for statement in scope_walk(node.body):
            if isinstance(statement, ast.Return) and isinstance(statement.value, _CHECKS):
                yield Hit(Span(path, statement.lineno, statement.col_offset + 1),
                          f"`{node.name}` returns `{ast.unparse(statement.value)}`: pytest "
                          "ignores what a test returns (it only warns), so the test passes "
                          "either way", f"Assert it: `assert {ast.unparse(statement.value)}`")


@rule("PYC052", "check-never-fails", Severity.ERROR,
      fix="Assert the condition itself: `assert x == y, 'message'`")
def check_never_fails(package: Package) -> Iterator[Hit]:
    """An `assert`, or a test, whose check can never fail.

    ## What it does
    Reports `assert (condition, 'message')` (the parentheses make a tuple of two) in every
    Python file of the package, and a test function (named as pytest's `python_functions`
    say, in a file under `test/` or `tests/`) that returns a comparison or an `and`/`or` of
    conditions instead of asserting it.

    ## Why is this bad?
    A non-empty tuple is always true, so the assert never fires (CPython only warns:
    "assertion is always true"); pytest ignores what a test returns (a
    `PytestReturnNotNoneWarning` at most). Either way the test passes whatever the code does,
    and `colcon test` reports success for a check that never ran.

    ## Example
    ```python
    def test_speed_limit():
        assert (limit(3.0) == 1.0, 'speed not limited')
    ```

    ## Use instead
    ```python
    def test_speed_limit():
        assert limit(3.0) == 1.0, 'speed not limited'
    ```
    """
    config = pytest_config(package)
    for path, _, tree in python_files(package, ("assert", "return")):
        yield from _tuple_asserts(path, tree)
        if config is not None and is_test_material(path):
            yield from _returned_checks(path, tree, config)
