"""PYC006: a literal called or indexed where a comma is missing (CPython's SyntaxWarning)."""

from __future__ import annotations

import ast
import warnings
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import python_files
from pkgtool.lazy_regex import lazy_pattern

_HINT = "; perhaps you missed a comma?"
_QUOTED = lazy_pattern(r"'(\w+)'")
_LITERALS = (ast.Constant, ast.Tuple, ast.List, ast.ListComp, ast.Set, ast.SetComp, ast.Dict,
             ast.DictComp, ast.GeneratorExp, ast.JoinedStr, ast.FormattedValue)
"""Every node kind CPython's compiler warns about when called or indexed (a superset)."""


def _may_warn(tree: ast.Module) -> bool:
    """True when some call or subscript applies to a literal: only then is compiling needed."""
    return any(isinstance(node, ast.Call) and isinstance(node.func, _LITERALS)
               or isinstance(node, ast.Subscript) and isinstance(node.value, _LITERALS)
               for node in nodes_of_class(tree, ast.Call, ast.Subscript))


def comma_warnings(path: str, tree: ast.Module) -> Iterator[tuple[int, str]]:
    """(line, text) of the "perhaps you missed a comma?" warnings compiling ``tree`` gives.

    Compiling runs nothing: it is the step of ``import`` that turns the syntax tree into
    bytecode, and the one that warns about literals that can never be called or indexed.
    """
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            compile(tree, path, "exec", dont_inherit=True)
        except (SyntaxError, ValueError, RecursionError, MemoryError):
            return
    for warning in caught:
        text = str(warning.message)
        if issubclass(warning.category, SyntaxWarning) and text.endswith(_HINT):
            yield warning.lineno, _QUOTED.sub(r"`\1`", text[: -len(_HINT)])


@rule("PYC006", "missing-comma", Severity.ERROR,
      fix="Add the missing comma between the two items")
def missing_comma(package: Package) -> Iterator[Hit]:
    """A literal is called or indexed: a comma between two items is missing.

    ## What it does
    Reports the code CPython itself warns about with "perhaps you missed a comma?": a
    tuple, list, string or number literal followed directly by parentheses or brackets, as
    in a list of tuples with a comma left out. Every Python file of the package is checked
    (setup.py, modules, launch files, tests).

    ## Why is this bad?
    `[('a', 1) ('b', 2)]` parses as calling the tuple `('a', 1)`, which raises `TypeError:
    'tuple' object is not callable` when the line runs: in setup.py's `data_files` that
    fails `colcon build`, in a node only the code path that reaches the line.

    ## Example
    ```python
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name])
        ('share/' + package_name, ['package.xml']),
    ]
    ```

    ## Use instead
    ```python
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ]
    ```
    """
    for path, _, tree in python_files(package):
        if _may_warn(tree):
            for line, problem in comma_warnings(path, tree):
                yield Hit(Span(path, line, 1), f"Missing comma: {problem}")
