"""LCH012: a file of the package named by a path relative to the package's source folder."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.launch._python_launch import launch_class, text_argument, within
from pkgtool.rules.registry import rule
from pkgtool.rules.relative_paths import package_file_named
from pkgtool.rules.syntax_trees import Index, launch_indexes

_SOURCES = ("launch.launch_description_sources", "launch_ros.actions", "launch_ros.descriptions")
"""The modules of the launch classes whose file arguments are read here."""


def _paths(call: ast.Call, index: Index, own: str) -> list[ast.expr]:
    """The file arguments of a launch call: each item of ``parameters=[...]`` of a launch_ros
    node, the items after an option in the ``arguments=[...]`` of a node of another package
    than ``own`` (``['-d', 'rviz/view.rviz']``: only a text naming a file of the package
    counts), the first argument of a launch description source, and the words of an
    ``ExecuteProcess`` command."""
    module, name = launch_class(call, index)
    if name == "ExecuteProcess" and within(module, ("launch.actions",)):
        return _command_words(call)
    if not within(module, _SOURCES):
        return []
    if name.endswith("LaunchDescriptionSource"):
        return call.args[:1] + [k.value for k in call.keywords if k.arg == "launch_file_path"]
    found: list[ast.expr] = []
    for keyword in call.keywords:
        if keyword.arg == "parameters" and isinstance(keyword.value, (ast.List, ast.Tuple)):
            found.extend(keyword.value.elts)
        elif keyword.arg == "arguments" and isinstance(keyword.value, (ast.List, ast.Tuple)) \
                and _other_package(call, own):
            items = keyword.value.elts
            found.extend(item for before, item in zip(items, items[1:])
                         if isinstance(before, ast.Constant) and
                         str(before.value).startswith("-"))
    return found


def _command_words(call: ast.Call) -> list[ast.expr]:
    """The words of an ``ExecuteProcess`` command list (``cmd=['python3', 'scripts/x.py']``),
    run from the directory ``ros2 launch`` was started in, unless ``cwd=`` says another."""
    if any(k.arg in ("cwd", None) for k in call.keywords):
        return []
    command = next((k.value for k in call.keywords if k.arg == "cmd"),
                   call.args[0] if call.args else None)
    return list(command.elts) if isinstance(command, (ast.List, ast.Tuple)) else []


def _other_package(call: ast.Call, own: str) -> bool:
    """True for a node of a package other than ``own`` (``rviz2``): a node of the package
    itself may resolve a relative argument against its own share folder."""
    package = next((k.value for k in call.keywords if k.arg == "package"), None)
    return isinstance(package, ast.Constant) and isinstance(package.value, str) and \
        package.value != own


def _argument_defaults(index: Index) -> dict[str, ast.expr]:
    """The ``default_value`` of each launch argument the file declares once, by name."""
    found: dict[str, list[ast.expr]] = {}
    for call in index.calls:
        module, name = launch_class(call, index)
        given = text_argument(call, "name")
        default = next((k.value for k in call.keywords if k.arg == "default_value"), None)
        if name == "DeclareLaunchArgument" and within(module, ("launch.actions",)) and \
                given is not None and default is not None:
            found.setdefault(given, []).append(default)
    return {name: values[0] for name, values in found.items() if len(values) == 1}


def _configuration_name(value: ast.expr, index: Index) -> str | None:
    """The argument ``LaunchConfiguration('name')`` reads."""
    if not isinstance(value, ast.Call) or len(value.args) != 1:
        return None
    module, name = launch_class(value, index)
    return text_argument(value, "variable_name") if name == "LaunchConfiguration" and \
        within(module, ("launch.substitutions",)) else None


def _written(package: Package) -> Iterator[tuple[str, Span]]:
    """The file paths the launch files write as literals where a file is read: Python's
    (:func:`_paths`) and the XML and YAML ones' (``<param from=>``, ``<include file=>``)."""
    for path, index in launch_indexes(package):
        defaults = _argument_defaults(index)
        for call in index.calls:
            for value in _paths(call, index, package.name):
                value = defaults.get(_configuration_name(value, index) or "", value)
                if isinstance(value, ast.Constant) and isinstance(value.value, str):
                    yield value.value, Span(path, value.lineno, value.col_offset + 1)
    for launch in package.launch_files:
        yield from launch.paths


@rule("LCH012", "relative-package-path", Severity.ERROR,
      fix="Build the path from the share folder: "
          "`PathJoinSubstitution([FindPackageShare('my_pkg'), 'config', 'params.yaml'])`, "
          "or `$(find-pkg-share my_pkg)/config/params.yaml` in XML and YAML")
def relative_package_path(package: Package) -> Iterator[Hit]:
    """A launch file names a file of its package by a path relative to the package.

    ## What it does
    Reports a string literal given as a parameter file of a launch_ros node
    (`parameters=['config/params.yaml']`, also as the default of the launch argument a
    `LaunchConfiguration` there reads) or after an option in the command line of a node of
    another package (`arguments=['-d', 'rviz/view.rviz']`), or as the file of a launch
    description source
    (`PythonLaunchDescriptionSource('launch/robot.launch.py')`) or a word of an
    `ExecuteProcess` command without `cwd=` (`cmd=['python3', 'scripts/tool.py']`) in a
    Python launch file, or
    as the `from` of a node's `<param>` (`param: [{from: ...}]` in YAML), the `file` of an
    `<include>` or the `filename` of a `<set_parameters_from_file>` in an XML or YAML launch
    file, that is a relative path to a file of this package's source folder, or one written
    from a workspace's folder (`src/my_pkg/config/params.yaml`).

    ## Why is this bad?
    A relative path is resolved against the folder `ros2 launch` runs in, not against the
    package: it finds the file only when launched from the package's source folder. Launched
    from anywhere else, as an installed package is, the node gets a parameter file that does
    not exist and fails to start (or the include fails), while it worked on the author's
    machine.

    ## Example
    ```python
    Node(package='my_pkg', executable='talker', parameters=['config/params.yaml'])
    ```

    ## Use instead
    ```python
    params = PathJoinSubstitution([FindPackageShare('my_pkg'), 'config', 'params.yaml'])
    Node(package='my_pkg', executable='talker', parameters=[params])
    ```
    ```xml
    <param from="$(find-pkg-share my_pkg)/config/params.yaml"/>
    ```
    """
    for text, span in _written(package):
        named = package_file_named(text, package)
        if named is None:
            continue
        inside, from_workspace = named
        if not from_workspace:
            yield Hit(span, f"`{text}` is relative to the folder `ros2 launch` runs in, not "
                      "to the package: the file is found only when launching from the "
                      "package's source folder")
        else:
            yield Hit(span, f"`{text}` is relative to the folder `ros2 launch` runs in: the "
                      f"package's `{inside}` is found only when launching from the "
                      "workspace's folder")
