"""LCH020: a launch argument built but never added, whose value the file reads without a
default."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import last_name, subtree
from pkgtool.model.launch_scopes import (overwritten_values, scope_nodes, simple_assignment,
                                         unread_values)
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.launch._python_launch import text_argument
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, launch_indexes

_DECLARE, _READ = "DeclareLaunchArgument", "LaunchConfiguration"


@rule("LCH020", "launch-argument-never-declared", Severity.ERROR,
      fix="Add the `DeclareLaunchArgument` action to the returned `LaunchDescription([...])`")
def launch_argument_never_declared(package: Package) -> Iterator[Hit]:
    """A Python launch file builds a `DeclareLaunchArgument` it never adds to the
    description, and reads the argument without a default.

    ## What it does
    Finds `DeclareLaunchArgument('name', ...)` actions assigned to a local name that the
    function never reads, or assigns again before reading it (`declare_x = ...` twice: the
    first is lost), when the file reads `LaunchConfiguration('name')` without a `default=`
    (in a substitution that is used: not one assigned to a name nothing reads) and declares
    `name` nowhere else.

    ## Why is this bad?
    Only actions in the returned description run: the argument is never declared, so
    `ros2 launch` stops with "launch configuration 'name' does not exist" unless the caller
    passes `name:=...`, and `--show-args` does not list it.

    ## Example
    ```python
    auto_start_arg = DeclareLaunchArgument('auto_start', default_value='true')
    node = Node(package='demo', executable='talker',
                parameters=[{'auto_start': LaunchConfiguration('auto_start')}])
    return LaunchDescription([node])
    ```

    ## Use instead
    ```python
    return LaunchDescription([auto_start_arg, node])
    ```
    """
    for path, index in launch_indexes(package):
        calls = index.calls
        if not any(last_name(c.func) == _DECLARE for c in calls):
            continue
        lost = {id(value) for function in index.functions
                for value in _lost_values(function, index)}
        declared = {name for c in calls if last_name(c.func) == _DECLARE and id(c) not in lost
                    and (name := text_argument(c, "name")) is not None}
        reads = {name: c for c in reversed(calls) if last_name(c.func) == _READ and len(c.args) < 2
                 and not index.inside(c, lost) and not any(k.arg == "default" for k in c.keywords)
                 and (name := text_argument(c, "variable_name")) is not None}
        for call in calls:
            name = text_argument(call, "name") if id(call) in lost and \
                last_name(call.func) == _DECLARE else None
            read = reads.get(name) if name is not None and name not in declared else None
            if read is not None:
                yield Hit(Span(path, call.lineno, call.col_offset + 1),
                          f"`DeclareLaunchArgument('{name}')` never reaches the launch "
                          f"description, and `LaunchConfiguration('{name}')` (line "
                          f"{read.lineno}) has no default: the launch fails with \"launch "
                          f"configuration '{name}' does not exist\" unless given `{name}:=...`")


def _lost_values(function: ast.FunctionDef | ast.AsyncFunctionDef, index: Index
                 ) -> set[ast.expr]:
    """The values the function assigns to a name it never reads, or assigns again first, or
    reads only inside such values (``mode = LaunchConfiguration('mode')`` read only by a
    node left out of the description, or only by a dict or tuple such a node alone reads)."""
    nodes = scope_nodes(function.body)
    lost = unread_values(function, nodes) | overwritten_values(function, nodes)
    loads: dict[str, list[ast.Name]] = {}
    for node in subtree(function):
        if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Load):
            loads.setdefault(node.id, []).append(node)
    assigned = [node for node in nodes if simple_assignment(node) and isinstance(
        node.value, (ast.Call, ast.Dict, ast.Tuple, ast.List))]  # type: ignore[attr-defined]
    grew = True
    while grew:
        ids = {id(value) for value in lost}
        more = {node.value for node in assigned  # type: ignore[attr-defined]
                if node.value not in lost and  # type: ignore[attr-defined]
                (reads := loads.get(node.targets[0].id)) and  # type: ignore[attr-defined]
                all(index.inside(read, ids) for read in reads)}
        lost |= more
        grew = bool(more)
    return lost
