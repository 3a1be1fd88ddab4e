"""LCH018: a launch action wrapped in a tuple by a stray comma is given to the launch."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.launch._python_launch import launch_class, own_nodes
from pkgtool.rules.registry import rule
from pkgtool.rules.scopes import bound_names
from pkgtool.rules.syntax_trees import Index, launch_indexes

_ACTION_MODULES = ("launch.actions", "launch_ros.actions")


def _tupled(function: ast.FunctionDef | ast.AsyncFunctionDef, index: Index
            ) -> dict[str, ast.Assign]:
    """The local names ``function`` binds once, to a one-item tuple holding a launch action
    (``node = Node(...),``), with their assignment."""
    bound = bound_names(function)
    found = {}
    for node in own_nodes(function, index):
        if isinstance(node, ast.Assign) and len(node.targets) == 1 and \
                isinstance(target := node.targets[0], ast.Name) and bound[target.id] == 1 and \
                isinstance(node.value, ast.Tuple) and len(node.value.elts) == 1 and \
                isinstance(item := node.value.elts[0], ast.Call) and \
                launch_class(item, index)[0].startswith(_ACTION_MODULES):
            found[target.id] = node
    return found


def _given(function: ast.FunctionDef | ast.AsyncFunctionDef, names: dict[str, ast.Assign],
           index: Index) -> Iterator[ast.Name]:
    """Reads of ``names`` that hand the tuple to the launch as one entity: an item of a list
    or tuple display given to ``LaunchDescription(...)``, or ``add_action(name)``."""
    for node in own_nodes(function, index):
        if not isinstance(node, ast.Call):
            continue
        if launch_class(node, index)[1] == "LaunchDescription" and node.args and \
                isinstance(node.args[0], (ast.List, ast.Tuple)):
            items = node.args[0].elts
        elif isinstance(node.func, ast.Attribute) and node.func.attr == "add_action":
            items = node.args[:1]
        else:
            continue
        yield from (item for item in items if isinstance(item, ast.Name) and item.id in names)


@rule("LCH018", "launch-action-in-a-tuple", Severity.ERROR,
      fix="Remove the comma after the action's closing parenthesis")
def launch_action_in_a_tuple(package: Package) -> Iterator[Hit]:
    """A launch action made a one-item tuple by a trailing comma is given to the launch.

    ## What it does
    In the package's Python launch files, reports a local name bound once to a launch action
    followed by a comma (`node = Node(...),`: a tuple holding the node), when the name is an
    item of the list given to `LaunchDescription([...])` or is passed to `add_action()`.

    ## Why is this bad?
    The launch receives a tuple where it expects an action: `ros2 launch` stops with
    "AttributeError: 'tuple' object has no attribute 'visit'" (or `describe`) before
    starting anything.

    ## Example
    ```python
    talker = Node(package='demo', executable='talker'),
    return LaunchDescription([talker])
    ```

    ## Use instead
    ```python
    talker = Node(package='demo', executable='talker')
    return LaunchDescription([talker])
    ```
    """
    for path, index in launch_indexes(package):
        for function in index.functions:
            names = _tupled(function, index)
            for read in _given(function, names, index) if names else ():
                assignment = names[read.id]
                yield Hit(Span(path, read.lineno, read.col_offset + 1),
                          f"`{read.id}` is a tuple holding the action, not the action: the "
                          f"comma after it on line {assignment.value.end_lineno} makes one, "
                          "and `ros2 launch` fails with AttributeError",
                          f"Remove the comma that ends line {assignment.value.end_lineno}")
