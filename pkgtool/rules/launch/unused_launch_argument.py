"""LCH024: a Python launch file declares an argument whose value nothing reads."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.launch._python_launch import (READ_BY_LAUNCH, launch_class, literal_arguments,
                                                 reads_shown)
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, launch_indexes


@rule("LCH024", "unused-launch-argument", Severity.WARNING,
      fix="Pass `LaunchConfiguration('<name>')` where the value is meant to go (a node's "
          "parameters, a condition), or remove the argument")
def unused_launch_argument(package: Package) -> Iterator[Hit]:
    """A Python launch file declares a launch argument whose value nothing reads.

    ## What it does
    Reports `DeclareLaunchArgument('name', ...)` in a Python launch file that reads no
    `LaunchConfiguration('name')` and names `name` in no other string (a dict key, a
    subscript of `context.launch_configurations`); not the ones launch reads itself for
    every process (`launch-prefix`, `launch-prefix-filter`, `emulate_tty`). Files that include
    other launch files, use an `OpaqueFunction`, `SetLaunchConfiguration` or a condition
    taking a configuration's name, load a parameter file with substitutions
    (`allow_substs=True`: `$(var name)` in the file reads it), build a name or read a
    configuration whose name is not a literal, or call helpers of modules other than
    launch's own and the standard library, are left alone: those may read the value where
    the file does not show it; and so are files that start nothing (declarations alone,
    which the files including them read).

    ## Why is this bad?
    `ros2 launch my_pkg robot.launch.py use_sim_time:=true` is accepted and listed by
    `--show-args`, yet changes nothing: the nodes keep their own values (wall-clock time,
    the default serial port, the default robot IP) and nothing says the value was ignored.

    ## Example
    ```python
    return LaunchDescription([
        DeclareLaunchArgument('use_sim_time', default_value='false'),
        Node(package='my_robot', executable='driver'),
    ])
    ```

    ## Use instead
    ```python
    return LaunchDescription([
        DeclareLaunchArgument('use_sim_time', default_value='false'),
        Node(package='my_robot', executable='driver',
             parameters=[{'use_sim_time': LaunchConfiguration('use_sim_time')}]),
    ])
    ```
    """
    for path, index in launch_indexes(package):
        found = literal_arguments(index)
        if found is None or not found[0] or not reads_shown(index) or \
                not _starts_something(index):
            continue
        declared, names, reads = found
        named = {id(call.args[0]) if call.args else
                 next(id(k.value) for k in call.keywords if k.arg == "name")
                 for call in declared}
        mentioned = {node.value for node in nodes_of_class(index.module_of(declared[0]),
                                                           ast.Constant)
                     if isinstance(node.value, str) and id(node) not in named}
        for call, name in zip(declared, names):
            if name not in reads and name not in mentioned and name not in READ_BY_LAUNCH:
                yield Hit(Span(path, call.lineno, call.col_offset + 1),
                          f"The launch argument `{name}` is declared but nothing reads its "
                          f"value: `{name}:=...` on the command line changes nothing")


def _starts_something(index: Index) -> bool:
    """True when the file makes a launch action other than declaring arguments (a node, a
    process, a group): a file of declarations alone is included by others, which read them."""
    return any(name != "DeclareLaunchArgument" and module.split(".")[1:2] == ["actions"]
               for module, name in (launch_class(call, index) for call in index.calls))
