"""LCH003: a Python launch file imports a package that package.xml does not declare."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.ros_names import LAUNCH_RUNTIME
from pkgtool.model.package import Package
from pkgtool.rules.imports import ANY, declaration, declared, launch_keys, needs
from pkgtool.rules.registry import rule


@rule("LCH003", "undeclared-launch-import", Severity.WARNING,
      fix="Add `<exec_depend>` entries for what the launch file imports (e.g. `launch_ros`)")
def undeclared_launch_import(package: Package) -> Iterator[Hit]:
    """A Python launch file imports a package that package.xml does not declare.

    ## What it does
    Checks the unguarded imports of `*.launch.py` files: `launch`, `launch_ros`,
    `ament_index_python` and anything else that is not standard library or the package's
    own must be an `<exec_depend>` (or `<depend>`). Declaring `ros2launch` covers `launch`,
    `launch_ros`, `launch_xml`, `launch_yaml` and `ament_index_python`.

    ## Why is this bad?
    A launch file installed with the package is part of its run-time interface: on a
    machine with only the declared dependencies, `ros2 launch` fails to import it. This is a
    warning because `ros2 launch` itself brings the core launch packages along.

    ## Example
    ```python
    from launch_ros.actions import Node  # package.xml declares rclpy only
    ```

    ## Use instead
    ```xml
    <exec_depend>ros2launch</exec_depend>
    ```
    """
    if package.manifest is None:
        return
    for launch in package.launch_files:
        if launch.python is None:
            continue
        available = launch_keys(package, launch.path)
        for need in needs(package, launch.python):
            if need.kind == "unknown" or any(k in available for k in need.keys):
                continue
            if need.top in LAUNCH_RUNTIME and "ros2launch" in available:
                continue
            other = declared(package, ANY).get(need.key)
            missing = f"`{need.key}` is declared only as {declaration(need.key, other)}" \
                if other else need.missing
            yield Hit(need.imported.span,
                      f"`{need.top}` is imported by a launch file but {missing}",
                      f"Add `<exec_depend>{need.key}</exec_depend>` to package.xml")
