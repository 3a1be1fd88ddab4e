"""PYC091: a service or action type is instantiated."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.interfaces import interface_kind
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import installed_trees

_KINDS = {"srv": ("Service", "Request"), "action": ("Action", "Goal")}
"""Interface modules whose classes rosidl makes impossible to instantiate, with what they
are called and the part a program makes instead."""


@rule("PYC091", "interface-class-instantiated", Severity.ERROR,
      fix="Make the request (goal) itself: `Trigger.Request()`, `Fibonacci.Goal()`")
def interface_class_instantiated(package: Package) -> Iterator[Hit]:
    """Code calls a service or action type as if it were a message.

    ## What it does
    Reports a call of a service or action type (`Trigger()`, `Spawn().Request()`,
    `Fibonacci()`) of a released interface package or one of the workspace, in installed
    modules.

    ## Why is this bad?
    A service or action type only groups its parts: rosidl's generated class raises
    `NotImplementedError: Service classes can not be instantiated` (Action classes alike),
    so the node dies where it meant to build a request or a goal.

    ## Example
    ```python
    request = Trigger().Request()
    ```

    ## Use instead
    ```python
    request = Trigger.Request()
    ```
    """
    for module, _, index in installed_trees(package):
        for call in index.calls:
            dotted = index.qualified(call.func) \
                if isinstance(call.func, (ast.Name, ast.Attribute)) else None
            parts = dotted.split(".") if dotted else []
            if len(parts) == 3 and parts[1] in _KINDS and _defines(package, *parts):
                kind, part = _KINDS[parts[1]]
                yield Hit(Span(module.path, call.lineno, call.col_offset + 1),
                          f"`{ast.unparse(call)}` instantiates the {kind.lower()} type "
                          f"`{parts[2]}`: rosidl raises NotImplementedError ({kind} classes "
                          f"can not be instantiated)", f"Write `{parts[2]}.{part}()`")


def _defines(package: Package, owner: str, kind: str, name: str) -> bool:
    """True when ``owner`` (released, or of the workspace) defines the ``kind`` ``name``."""
    other = package.context.workspace.get(owner)
    if other is not None and other.interfaces:
        return name in other.interfaces.get(kind, ())
    return interface_kind(owner, name, package.context.distro) == kind
