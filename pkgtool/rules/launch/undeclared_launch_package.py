"""LCH002: a launch file uses another package that package.xml does not declare."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.imports import RUNTIME, TEST, declared, is_test_launch
from pkgtool.rules.launch._python_launch import launch_tests
from pkgtool.rules.package_lookups import unlisted_packages
from pkgtool.rules.registry import rule


@rule("LCH002", "undeclared-launch-package", Severity.ERROR,
      fix="Add an `<exec_depend>` for the package to package.xml")
def undeclared_launch_package(package: Package) -> Iterator[Hit]:
    """A launch file starts nodes of, includes from, or reads files of an undeclared package.

    ## What it does
    Collects the packages a launch file names statically: `Node(package=...)`,
    `get_package_share_directory(...)`, `FindPackageShare(...)`, `$(find-pkg-share ...)` in
    XML and YAML launch files, the package of `ExecutableInPackage(exe, pkg)` and
    `$(exec-in-pkg exe pkg)`, the MoveIt config package `MoveItConfigsBuilder('panda')`
    finds, the package a launch file's own helper looks up by the name it is given
    (`load_yaml('panda_moveit_config', 'kinematics.yaml')` where `load_yaml` calls
    `get_package_share_directory(package_name)` on every call: not under an `if`, a loop or a
    `try`, nor after a `return`; the helper defined once, undecorated, its name bound nowhere
    else), `xacro`'s package for a
    command substitution running it (`Command(['xacro ', path])`, `$(command 'xacro ...')`),
    and the package of a process `ExecuteProcess` starts: `ros2 run pkg exe`, `ros2 launch
    pkg file`, or a program of a ROS package (`cmd=['rviz2', '-d', config]`; also an XML or
    YAML `executable`'s `cmd`), and the rosdep key of a terminal or tool a node or process
    runs in (`prefix='xterm -e'`, `launch-prefix="gnome-terminal --"`, `valgrind`).
    A name that is no package of
    the target's release nor of the packages linted with it (the workspace pkgtool sees) is
    said so, with the package (of the workspace, this one or the release) it is a typo of,
    if any. Each one other than this
    package must be an `<exec_depend>` or `<depend>` (a `<test_depend>` for launch files
    under `test/` and for `launch_testing` tests, whose `generate_test_description` starts
    nodes too), or be brought in by a released metapackage declared so (`ros2_control`
    brings `controller_manager`;
    metapackages nest, but a regular package's own dependencies never count).
    Packages used only after the launch file checked that they are installed (`if 'nav2_bringup'
    in get_packages_with_prefixes():`, or in a `try` that catches `PackageNotFoundError`,
    or one that looks a package up and catches `KeyError`, `Exception` or anything, with a
    handler that goes on rather than raising again or exiting; or under `if flag:` where the
    flag is set to `True` in such a `try`, or is what a function of the file with such a
    `try` returns, `has_mux = package_available('twist_mux')`) are optional and left alone,
    and so is a node that is never started: one assigned to a local
    name its function never reads (`rviz = Node(package='rviz2', ...)` left out of the
    LaunchDescription), with the `FindPackageShare` substitutions inside it, which only a
    started action performs. `get_package_share_directory` runs when the file does and is
    always checked. A workspace package that depends on this one (itself or through other
    workspace packages) is left alone too: declaring it would make a dependency cycle, which
    colcon cannot order (xarm_ros2's MoveIt launch files look up its planner so). A package
    package.xml declares only inside a comment is reported with no fix: it may be left out on
    purpose (MoveIt's resources leave `warehouse_ros_mongo` out so, to spare the build farm a
    cycle).

    ## Why is this bad?
    `ros2 launch` fails with "package not found" on machines set up with rosdep, because
    nothing told rosdep to install the package.

    ## Example
    ```python
    Node(package='robot_state_publisher', executable='robot_state_publisher')
    ```

    ## Use instead
    ```xml
    <exec_depend>robot_state_publisher</exec_depend>
    ```
    """
    if package.manifest is None:
        return
    tests = {launch.path for launch in launch_tests(package)}
    for launch in (*package.launch_files, *launch_tests(package)):
        test = launch.path in tests or is_test_launch(launch.path)
        available = declared(package, RUNTIME | TEST) if test else \
            declared(package, RUNTIME)
        used = [(n.package, n.package_span or n.span) for n in launch.nodes
                if n.package and not n.optional and not n.unused] + [
            (p.package, p.span) for p in launch.packages if not p.optional and not p.unused]
        yield from unlisted_packages(package, used, available, "a launch file",
                                     "test_depend" if test else "exec_depend")
