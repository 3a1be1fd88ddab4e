"""LCH016: a launch file uses an attribute ``LaunchDescription`` does not have."""

from __future__ import annotations

import ast
from collections.abc import Iterator
from difflib import get_close_matches

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.launch_api import LAUNCH_DESCRIPTION_ATTRIBUTES
from pkgtool.model.ast_nodes import subtree
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.launch._python_launch import launch_class
from pkgtool.rules.registry import rule
from pkgtool.rules.scopes import bound_names
from pkgtool.rules.syntax_trees import Index, launch_indexes


def _descriptions(function: ast.FunctionDef | ast.AsyncFunctionDef, index: Index
                  ) -> set[str]:
    """The local names ``function`` binds once, to ``LaunchDescription(...)``."""
    bound = bound_names(function)
    return {target.id for node in subtree(function) if isinstance(node, ast.Assign)
            and len(node.targets) == 1 and isinstance(target := node.targets[0], ast.Name)
            and bound[target.id] == 1 and isinstance(node.value, ast.Call)
            and launch_class(node.value, index)[1] == "LaunchDescription"
            and index.enclosing_function(node) is function}


@rule("LCH016", "unknown-launch-description-method", Severity.ERROR,
      fix="Call a method LaunchDescription has (`add_action`)")
def unknown_launch_description_method(package: Package) -> Iterator[Hit]:
    """A Python launch file uses an attribute that `LaunchDescription` does not have.

    ## What it does
    In the package's Python launch files, follows each local name a function binds once, to
    `LaunchDescription(...)`, and reports a read of a public attribute the class lacks
    (`ld.add_actions(node)`, `ld.addAction(node)`, `ld.add_node(node)`), with the attribute
    spelled like it when there is one. `LaunchDescription`'s attributes: `add_action`,
    `add_entity`, `entities`, `get_launch_arguments`, `describe`... (launch, Humble to
    Rolling).

    ## Why is this bad?
    `ros2 launch` calls `generate_launch_description()` first: the read raises
    `AttributeError` and nothing is launched.

    ## Example
    ```python
    ld = LaunchDescription()
    ld.add_actions(talker)
    return ld
    ```

    ## Use instead
    ```python
    ld = LaunchDescription()
    ld.add_action(talker)
    return ld
    ```
    """
    for path, index in launch_indexes(package):
        for function in index.functions:
            names = _descriptions(function, index)
            for node in subtree(function) if names else ():
                if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and \
                        node.value.id in names and not node.attr.startswith("_") and \
                        node.attr not in LAUNCH_DESCRIPTION_ATTRIBUTES and \
                        index.enclosing_function(node) is function:
                    close = get_close_matches(node.attr, sorted(LAUNCH_DESCRIPTION_ATTRIBUTES),
                                              n=1)
                    yield Hit(Span(path, node.lineno, node.col_offset + 1),
                              f"`{node.value.id}` is a `LaunchDescription`, which has no "
                              f"`{node.attr}`: `ros2 launch` fails with AttributeError",
                              f"Write `{close[0]}`" if close else None)
