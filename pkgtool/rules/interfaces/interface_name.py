"""IFC001: an interface file whose name rosidl refuses (``robot_status.msg``)."""

from __future__ import annotations

import re
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.interfaces._files import MESSAGE_NAME, built_interface_files
from pkgtool.rules.registry import rule

_SUFFIXES = ("_Request", "_Response", "_Goal", "_Result", "_Feedback")
"""Suffixes rosidl strips before it checks a name (those of the classes it derives)."""


@rule("IFC001", "invalid-interface-name", Severity.ERROR,
      fix="Rename the file in CamelCase (`RobotStatus.msg`) and the imports that name it")
def invalid_interface_name(package: Package) -> Iterator[Hit]:
    """An interface file's name is not a valid ROS 2 interface name.

    ## What it does
    Reports a `.msg`, `.srv` or `.action` file of a ROS 2 package whose name (without its
    suffix) does not start with an upper-case letter followed by letters and digits only:
    `robot_status.msg`, `Add_Two.srv`, `moveArm.action`. rosidl takes the interface's name
    from the file name and checks it against `[A-Z][A-Za-z0-9]*`. Only the files the
    CMakeLists.txt passes to `rosidl_generate_interfaces` are checked (listed, through a
    variable it sets, or by a glob); ROS 1 (catkin) packages are left alone.

    ## Why is this bad?
    `colcon build` fails in `rosidl_generate_interfaces` ("is an invalid message name"), so
    no interface of the package is generated and every node importing one fails.

    ## Example
    ```text
    msg/robot_status.msg
    ```

    ## Use instead
    ```text
    msg/RobotStatus.msg      # from my_interfaces.msg import RobotStatus
    ```
    """
    for found in built_interface_files(package):
        name = found.name
        for suffix in _SUFFIXES:
            name = name.removesuffix(suffix)
        if not MESSAGE_NAME.fullmatch(name.removeprefix("Sample_")):
            meant = camel_case(found.name)
            yield Hit(Span(found.path, 1, 1),
                      f"`{found.path}` is named `{found.name}`, which rosidl refuses: interface "
                      "names start with an upper-case letter and hold only letters and digits",
                      f"Rename it `{meant}.{found.kind}`" if MESSAGE_NAME.fullmatch(meant)
                      else None)


def camel_case(name: str) -> str:
    """``name`` in the CamelCase rosidl wants (``robot_status`` gives ``RobotStatus``)."""
    return "".join(part[:1].upper() + part[1:] for part in re.split(r"[^A-Za-z0-9]+", name))
