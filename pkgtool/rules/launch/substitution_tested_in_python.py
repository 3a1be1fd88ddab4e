"""LCH023: a launch substitution tested or compared in Python (``if use_rviz:``), where it is
an object, not the value launch gives it later."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.span import Span
from pkgtool.model.package import Package
from pkgtool.rules.launch._python_launch import (first_substitution, launch_function_nodes,
                                                 substitution_made)
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index

_EQUALITY = (ast.Eq, ast.NotEq)
_TESTS = (ast.If, ast.While, ast.IfExp, ast.Assert)
"""What tests an expression for truth: ``if``, ``while``, ``x if test else y``, ``assert``."""


def _operands(test: ast.expr) -> Iterator[ast.expr]:
    """``test`` and, through ``not``, ``and`` and ``or``, the expressions it tests."""
    yield test
    if isinstance(test, ast.UnaryOp) and isinstance(test.op, ast.Not):
        yield from _operands(test.operand)
    elif isinstance(test, ast.BoolOp):
        for value in test.values:
            yield from _operands(value)


def _text(node: ast.expr) -> bool:
    return isinstance(node, ast.Constant) and isinstance(node.value, str)


@rule("LCH023", "substitution-tested-in-python", Severity.ERROR,
      fix="Decide when the launch runs: `condition=IfCondition(LaunchConfiguration('x'))`, or "
          "read the value with `.perform(context)` in an `OpaqueFunction`")
def substitution_tested_in_python(package: Package) -> Iterator[Hit]:
    """A launch substitution is tested for truth or compared with text in Python.

    ## What it does
    In the functions of Python launch files, reports a substitution of `launch.substitutions`
    or `launch_ros.substitutions` (a call such as `LaunchConfiguration('use_rviz')`, or a
    name the function binds once, to one) tested by `if`, `while`, a conditional expression,
    `assert`, `not`, `and` or `or`, or compared with a string by `==` or `!=`.

    ## Why is this bad?
    While `generate_launch_description` runs, a substitution is an object: launch gives it a
    value only later, when it runs the description. The object is always true, and never
    equal to a string, so the branch is decided once for every launch, whatever the user
    passes (`use_rviz:=false` still starts RViz).

    ## Example
    ```python
    use_rviz = LaunchConfiguration('use_rviz')
    if use_rviz == 'true':
        actions.append(Node(package='rviz2', executable='rviz2'))
    ```

    ## Use instead
    ```python
    use_rviz = LaunchConfiguration('use_rviz')
    actions.append(Node(package='rviz2', executable='rviz2',
                        condition=IfCondition(use_rviz)))
    ```
    """
    for path, index, single, node in launch_function_nodes(package):
        if isinstance(node, _TESTS):
            yield from _tested(path, node.test, index, single)  # type: ignore[attr-defined]
        elif isinstance(node, ast.Compare) and len(node.ops) == 1 and \
                isinstance(node.ops[0], _EQUALITY):
            yield from _compared(path, node, index, single)


def _tested(path: str, test: ast.expr, index: Index, single: dict[str, ast.expr]
            ) -> Iterator[Hit]:
    """A hit for each substitution ``test`` tests for truth (through ``not``, ``and``,
    ``or``)."""
    for operand in _operands(test):
        made = substitution_made(operand, index, single)
        if made:
            yield Hit(Span(path, operand.lineno, operand.col_offset + 1),
                      f"`{ast.unparse(operand)}` is a `{made}` object here, always true: the "
                      "test takes the same branch whatever value launch gives it")


def _compared(path: str, compare: ast.Compare, index: Index, single: dict[str, ast.expr]
              ) -> Iterator[Hit]:
    """A hit for a substitution compared with a string (never equal: no ``__eq__``)."""
    sides = (compare.left, compare.comparators[0])
    made = first_substitution(sides, index, single)
    if made and any(_text(side) for side in sides):
        result = "False" if isinstance(compare.ops[0], ast.Eq) else "True"
        yield Hit(Span(path, compare.lineno, compare.col_offset + 1),
                  f"`{ast.unparse(compare)}` compares a `{made}` object with text: it is "
                  f"always {result}, whatever value launch gives the substitution")
