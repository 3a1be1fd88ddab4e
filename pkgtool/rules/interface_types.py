"""What DEP008 and DEP009 share: the interfaces a package name stands for, where known.

Known are the package's own ``msg/``, ``srv/`` and ``action/`` folders with the other files
its CMakeLists.txt (or a CMake file of the package it includes) passes to
``rosidl_generate_interfaces`` (nothing is known of a package
that passes files a found package lists), those of the other packages of the workspace, and
(for a jazzy target) the shipped table of the Jazzy interface wheels
(:mod:`pkgtool.knowledge.interfaces`), in that order. Anything else is unknown: no finding. A
ROS 1 (catkin) package knows only its own interfaces, laid out as ROS 1 generates them: an
action ``A`` is the messages ``AAction``, ``AGoal``, ... of ``pkg.msg``.
"""

from __future__ import annotations

import ast

from pkgtool.knowledge.interfaces import KINDS, Interfaces, interfaces_of
from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.model.cmake_interfaces import with_listed
from pkgtool.model.context import interface_file
from pkgtool.model.installed import cmake_text
from pkgtool.model.memo import per_package
from pkgtool.model.package import Package
from pkgtool.rules.ros1_platform import is_ros1_package
from pkgtool.rules.syntax_trees import installed_modules

ROS1_ACTION_MESSAGES = ("Action", "ActionGoal", "ActionResult", "ActionFeedback", "Goal",
                        "Result", "Feedback")
"""The messages catkin's actionlib generates for each action ``A`` (``AActionGoal``, ...)."""


@per_package
def own_interfaces(package: Package) -> Interfaces | None:
    """Kind -> names of the package's interfaces: the files of its kind folders and those its
    CMakeLists.txt lists; None when that list takes files from another package."""
    found: dict[str, set[str]] = {}
    for kind, name in filter(None, map(interface_file, package.files)):
        found.setdefault(kind, set()).add(name)
    return with_listed({kind: frozenset(names) for kind, names in found.items()},
                       cmake_text(package), package.files)


def ros1_layout(interfaces: Interfaces) -> Interfaces:
    """``interfaces`` as ROS 1 Python modules hold them: actions as messages, no ``action``,
    and each service ``X`` with its ``XRequest`` and ``XResponse`` classes."""
    actions = interfaces.get("action", frozenset())
    messages = interfaces.get("msg", frozenset()) | {
        action + suffix for action in actions for suffix in ROS1_ACTION_MESSAGES}
    services = interfaces.get("srv", frozenset())
    layout = {kind: names for kind, names in interfaces.items() if kind != "action"}
    if services:
        layout["srv"] = services | {f"{service}{part}" for service in services
                                    for part in ("Request", "Response")}
    return {**layout, "msg": messages} if messages else layout


def interfaces_for(package: Package, name: str) -> Interfaces | None:
    """The interfaces of the package called ``name`` as seen from ``package``, or None.

    For a ROS 1 package only its own are known (the workspace index and the tables describe
    ROS 2's layout).
    """
    ros1 = is_ros1_package(package)
    if name == package.name:
        own = own_interfaces(package)
        if own is None:
            return None
        return (ros1_layout(own) if ros1 else own) or None
    if ros1:
        return None
    neighbour = package.context.workspace.get(name)
    if neighbour is not None and neighbour.interfaces:
        return neighbour.interfaces
    return interfaces_of(name, package.context.distro)


@per_package
def patched_interfaces(package: Package) -> frozenset[tuple[str, str, str]]:
    """(package, kind, name) that the package's installed code assigns onto an interface
    module, as ROS 1 compatibility shims do (``rosgraph_msgs.msg.Log = rcl_interfaces.msg.Log``):
    importable once that code has run."""
    found: set[tuple[str, str, str]] = set()
    for _, tree in installed_modules(package):
        for node in nodes_of_class(tree, ast.Assign, ast.AnnAssign, ast.AugAssign):
            targets = node.targets if isinstance(node, ast.Assign) else [
                node.target] if isinstance(node, (ast.AnnAssign, ast.AugAssign)) else []
            for target in targets:
                owner = target.value if isinstance(target, ast.Attribute) else None
                if (isinstance(owner, ast.Attribute) and owner.attr in KINDS
                        and isinstance(owner.value, ast.Name)):
                    found.add((owner.value.id, owner.attr, target.attr))  # type: ignore
    return frozenset(found)
