"""DEP008: a message, service or action imported that its package does not define."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.interfaces import KINDS, WORDS, Mismatch, mismatch
from pkgtool.model.package import Package
from pkgtool.rules.imports import all_python
from pkgtool.rules.dependencies.interface_types import interfaces_for
from pkgtool.rules.registry import rule


@rule("DEP008", "unknown-interface-import", Severity.ERROR,
      fix="Import an interface the package defines, from the module of its kind")
def unknown_interface_import(package: Package) -> Iterator[Hit]:
    """``from pkg.msg import Name`` names no message of ``pkg`` (or a service or action).

    ## What it does
    Checks the names of unguarded `from <pkg>.msg|srv|action import ...` imports in every
    Python file against the interfaces of `<pkg>` when they are known: the package's own
    `msg/`, `srv/` and `action/` folders (their subfolders too: rosidl flattens
    `msg/motion/Twist.msg` into `msg/Twist`) and the other files its CMakeLists.txt passes to
    `rosidl_generate_interfaces` (none are known when it passes a list that a package it
    finds sets, such as `${pkg_MSG_FILES}`), those of the other packages of the workspace, and
    pkgtool's table of the interface packages of ROS 2 Jazzy that are installable as wheels
    (for a jazzy target only: other distributions have other interfaces)
    (`std_msgs`, `geometry_msgs`, `sensor_msgs`, `std_srvs`, ...). Packages that are not
    known (`nav2_msgs`) are never reported. The types generated with each service `X`
    (`X_Request`, `X_Response`, `X_Event`) and action `A` (`A_SendGoal_Request`,
    `A_GetResult_Response`, ...) exist where the target distribution's modules export them:
    since Iron; on humble they are reported with the attribute to use (`X.Request`). A ROS 1
    (catkin) package is checked against its own interfaces only, where an action `A` is the
    messages `AAction`, `AGoal`, `AResult`, ... of `pkg.msg`.

    ## Why is this bad?
    The node dies at start-up with `ImportError: cannot import name ...`; a service imported
    from `.msg` fails the same way, and only on the robot.

    ## Example
    ```python
    from std_msgs.msg import Strin
    from std_srvs.msg import Trigger
    ```

    ## Use instead
    ```python
    from std_msgs.msg import String
    from std_srvs.srv import Trigger
    ```
    """
    for module in all_python(package):
        for imported in module.imports:
            parts = imported.module.split(".")
            if imported.level or imported.guarded or len(parts) != 2 or parts[1] not in KINDS:
                continue
            known = interfaces_for(package, parts[0])
            if known is None:
                continue
            for name in imported.names:
                found = None if name == "*" else mismatch(
                    parts[0], parts[1], name, known, package.context.distro)
                if found:
                    yield Hit(imported.span, _message(found), _fix(found))


def _message(found: Mismatch) -> str:
    module = f"{found.package}.{found.kind}"
    if found.companion:
        return (f"`{module}` exports `{found.name}` only since Iron, not on {found.distro}: "
                f"use `{found.companion}`")
    if found.actual:
        return (f"`{found.name}` is a {WORDS[found.actual]} of `{found.package}`, not a "
                f"{WORDS[str(found.kind)]}: `{module}` has no `{found.name}`")
    text = f"`{module}` has no {WORDS[str(found.kind)]} `{found.name}`"
    if found.close:
        kind, name = found.close
        text += f" (did you mean `{name}`?)" if kind == found.kind else (
            f" (did you mean the {WORDS[kind]} `{name}` of `{found.package}.{kind}`?)")
    return text


def _fix(found: Mismatch) -> str | None:
    if found.companion:
        return f"Import `{found.companion.split('.', 1)[0]}` and use `{found.companion}`"
    kind, name = (found.actual, found.name) if found.actual else found.close or (None, None)
    return f"Write `from {found.package}.{kind} import {name}`" if kind else None
