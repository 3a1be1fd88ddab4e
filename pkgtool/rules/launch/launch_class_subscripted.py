"""LCH026: a class of launch or launch_ros indexed with ``[...]`` where it is meant to be
called."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity, shortened
from pkgtool.lazy_regex import lazy_pattern
from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import launch_trees

_MODULES = ("launch.", "launch_ros.")
"""Where the classes come from (``launch.substitutions.PathJoinSubstitution``)."""
_CLASS_NAME = lazy_pattern(r"[A-Z][a-z]+(?:[A-Z][a-z0-9]*)*")
"""A class's name (``PathJoinSubstitution``), not a constant's
(``SomeSubstitutionsType_types_tuple``)."""


@rule("LCH026", "launch-class-subscripted", Severity.ERROR,
      fix="Call the class: `PathJoinSubstitution([...])`, not `PathJoinSubstitution[...]`")
def launch_class_subscripted(package: Package) -> Iterator[Hit]:
    """A Python launch file indexes a class of launch or launch_ros instead of calling it.

    ## What it does
    Reports `Name[...]` in Python launch files where `Name` is a class imported from
    `launch` or `launch_ros` (a capitalised name of their modules:
    `PathJoinSubstitution[share, 'file.yaml']`, `Node[...]`), outside annotations.

    ## Why is this bad?
    These classes are no generic types: indexing one raises `TypeError: type
    'PathJoinSubstitution' is not subscriptable` while `generate_launch_description()` runs,
    and `ros2 launch` starts nothing. The brackets were meant to be the list the class is
    called with.

    ## Example
    ```python
    config = PathJoinSubstitution[FindPackageShare('demo'), 'config', 'params.yaml']
    ```

    ## Use instead
    ```python
    config = PathJoinSubstitution([FindPackageShare('demo'), 'config', 'params.yaml'])
    ```
    """
    for path, tree, index in launch_trees(package):
        if not any(target.startswith(_MODULES) for target in index.aliases.values()):
            continue
        for node in nodes_of_class(tree, ast.Subscript):
            assert isinstance(node, ast.Subscript)
            qualified = index.qualified(node.value) if isinstance(
                node.value, (ast.Name, ast.Attribute)) else None
            if qualified is None or not qualified.startswith(_MODULES) or \
                    not _CLASS_NAME.fullmatch(qualified.rpartition(".")[2]) or \
                    index.annotation_holder(node) is not None:
                continue
            yield Hit(Span(path, node.lineno, node.col_offset + 1),
                      f"`{shortened(ast.unparse(node))}` indexes the class "
                      f"`{qualified.rpartition('.')[2]}` of `{qualified.rpartition('.')[0]}`: "
                      "it is no generic type, and the launch fails with TypeError (not "
                      "subscriptable)",
                      f"Call it: `{ast.unparse(node.value)}([...])`")
