"""LCH017: a launch file starts a launch file as if it were a node's executable."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.launch import LAUNCH_FILE_NAME
from pkgtool.model.package import Package
from pkgtool.rules.launch._executables import installs_program
from pkgtool.rules.registry import rule


@rule("LCH017", "launch-file-as-executable", Severity.ERROR,
      fix="Include the launch file with `IncludeLaunchDescription` (`<include file=...>`)")
def launch_file_as_executable(package: Package) -> Iterator[Hit]:
    """A launch file starts another launch file as a node's executable.

    ## What it does
    Reports a `Node(executable=...)` (`<node exec=...>`) whose executable is named like a
    launch file: `bringup_launch.py`, `robot.launch.py`, `sim.launch.xml`, of any package;
    not one its package installs as a program under that name (a node script called
    `rosapi_launch.py` that CMake's `install(PROGRAMS ...)` puts into `lib/<package>`).

    ## Why is this bad?
    `Node` runs a program from the package's `lib/<package>` folder; launch files are
    installed to `share/<package>/launch` and are read by `ros2 launch`, never run. The launch
    stops with "executable not found" (the package installs none of that name), and the
    launch file meant to run never does.

    ## Example
    ```python
    Node(package='nav2_bringup', executable='bringup_launch.py')
    ```

    ## Use instead
    ```python
    IncludeLaunchDescription(PythonLaunchDescriptionSource(
        PathJoinSubstitution([FindPackageShare('nav2_bringup'), 'launch',
                              'bringup_launch.py'])))
    ```
    """
    for launch in package.launch_files:
        for node in launch.nodes:
            if node.executable and not node.unused and \
                    LAUNCH_FILE_NAME.search(node.executable) and \
                    not installs_program(package, node.package or package.name, node.executable):
                owner = node.package or "<package>"
                yield Hit(node.executable_span or node.span,
                          f"`{node.executable}` is a launch file, not an executable of "
                          f"`{owner}`: launch looks for a program of that name in "
                          f"`lib/{owner}` and stops (\"executable not found\")",
                          "Include it with `IncludeLaunchDescription(...)` (XML: `<include "
                          f"file=\"$(find-pkg-share {owner})/launch/{node.executable}\"/>`)")
