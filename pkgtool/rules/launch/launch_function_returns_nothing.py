"""LCH006: ``generate_launch_description`` returns nothing."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.python_visitor import parse_tree
from pkgtool.model.span import Span
from pkgtool.rules.launch._python_launch import FUNCTION
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import python_launch_files
from pkgtool.rules.scopes import returns_none, scope_walk

_COLLECTIONS = {ast.List: "list", ast.Tuple: "tuple", ast.ListComp: "list"}
"""What a launch function returns instead of a description, by syntax."""


def _launch_function(tree: ast.AST) -> ast.FunctionDef | None:
    """The module's one top-level ``def generate_launch_description``, if defined once."""
    found = [node for node in getattr(tree, "body", ())
             if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef))
             and node.name == FUNCTION]
    bound = [node for node in getattr(tree, "body", ()) if isinstance(node, ast.Assign) and any(
        isinstance(t, ast.Name) and t.id == FUNCTION for t in node.targets)]
    return found[0] if len(found) == 1 and not bound and \
        isinstance(found[0], ast.FunctionDef) else None


@rule("LCH006", "launch-function-returns-nothing", Severity.ERROR,
      fix="Return the description: `return LaunchDescription([...])`")
def launch_function_returns_nothing(package: Package) -> Iterator[Hit]:
    """`generate_launch_description()` builds a description but never returns it.

    ## What it does
    Reports a Python launch file whose top-level `generate_launch_description` has no
    `return <value>` and no `yield` anywhere in its own body (nested functions do not count),
    so that calling it gives None, or that returns a list or a tuple (`return [talker,
    listener]`) instead of a `LaunchDescription` of them. Functions that are decorated, that
    are placeholders (only `pass`, `...`, a docstring or `raise`), or that the module defines
    or assigns more than once are left alone.

    ## Why is this bad?
    `ros2 launch` calls the function and uses what it returns as the launch description;
    with None or a list nothing starts and the launch stops with an error instead of the
    nodes (`'list' object has no attribute
    'get_launch_arguments_with_include_launch_description_actions'`).

    ## Example
    ```python
    def generate_launch_description():
        talker = Node(package='my_pkg', executable='talker')
        LaunchDescription([talker])
    ```

    ## Use instead
    ```python
    def generate_launch_description():
        talker = Node(package='my_pkg', executable='talker')
        return LaunchDescription([talker])
    ```
    """
    for path, _module, text in python_launch_files(package):
        function = _launch_function(parse_tree(path, text))
        if function is not None and returns_none(function):
            yield Hit(Span(path, function.lineno, function.col_offset + 1),
                      f"`{FUNCTION}()` returns nothing: `ros2 launch` gets None and starts "
                      "nothing")
        for node in scope_walk(function.body) if function is not None else ():
            if isinstance(node, ast.Return) and type(node.value) in _COLLECTIONS:
                yield Hit(Span(path, node.lineno, node.col_offset + 1),
                          f"`{FUNCTION}()` returns a {_COLLECTIONS[type(node.value)]}, not a "
                          "`LaunchDescription`: `ros2 launch` fails with AttributeError",
                          "Wrap it: `return LaunchDescription([...])`")
