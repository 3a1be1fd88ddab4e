"""PYC035: a publisher or subscription given a service or action type, a service or client
something other than a service type, an action client or server no action type."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.interfaces import interface_kind, is_known_package
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import (ACTION_PARAMETERS, ACTIONS, PARAMETERS, argument,
                                    node_api_calls)
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, installed_trees
from pkgtool.lazy_regex import lazy_pattern

_KIND = lazy_pattern(r"(?P<package>\w+)\.(?P<kind>msg|srv|action)\.(?P<name>\w+)(?P<part>\.\w+)?")
"""An imported interface class: ``std_msgs.msg.String``, ``std_srvs.srv.Trigger.Request``."""
_MESSAGE_PARTS = {"srv": (".Request", ".Response"),
                  "action": (".Goal", ".Result", ".Feedback")}
"""The message classes a service or action type holds."""
_WANTED = {"msg_type": "a message type", "srv_type": "a service type",
           "action_type": "an action type"}


def _given(qualified: str, distro: str) -> str | None:
    """What an imported interface class is, or None when it is not one (or not what its
    import says: an interface of a known package that is of another kind, DEP008's)."""
    found = _KIND.fullmatch(qualified)
    if found is None:
        return None
    kind, part = found.group("kind"), found.group("part")
    package, name = found.group("package"), found.group("name")
    if is_known_package(package, distro) and interface_kind(package, name, distro) != kind:
        return None
    if part is None:
        return {"msg": "a message type", "srv": "a service type",
                "action": "an action type"}[kind]
    return "a message type" if part in _MESSAGE_PARTS.get(kind, ()) else None


_BUILTIN_TYPES = frozenset({"bool", "int", "float", "str", "bytes", "list", "dict", "tuple",
                            "set", "object", "complex", "bytearray"})
"""Python's own types, which a node sometimes gives where an interface type is wanted."""
_STD_MSGS = {"bool": "Bool", "int": "Int64", "float": "Float64", "str": "String"}
"""The std_msgs message wrapping a value of each Python type."""


def _builtin_type(value: ast.expr, index: Index) -> str | None:
    """The name of the Python type ``value`` is (``bool``), unless the module binds the name."""
    return value.id if isinstance(value, ast.Name) and value.id in _BUILTIN_TYPES and \
        value.id not in index.bound else None


def _checked(package: Package) -> Iterator[tuple[str, ast.expr, str, str]]:
    """(file, type argument, the call's name, the parameter) of the calls taking a type."""
    for module, call, method, _ in node_api_calls(package):
        parameter = PARAMETERS[method][0]
        value = argument(call, PARAMETERS[method], parameter)
        if value is not None:
            yield module.path, value, f"{method}()", parameter
    for module, _, index in installed_trees(package):
        for call in index.calls:
            if index.qualified(call.func) in ACTIONS:
                value = argument(call, ACTION_PARAMETERS, "action_type")
                if value is not None:
                    yield module.path, value, f"{ast.unparse(call.func)}()", "action_type"


def _instance_published(value: ast.expr, api: str, index: Index, distro: str) -> bool:
    """True for a publisher given a message built from its class (``String()``), not the
    class (checked on Jazzy: creating works, publishing raises)."""
    return api in ("create_publisher()", "create_lifecycle_publisher()") and \
        isinstance(value, ast.Call) and isinstance(value.func, (ast.Name, ast.Attribute)) and \
        _given(index.qualified(value.func) or "", distro) == "a message type"


@rule("PYC035", "interface-of-another-kind", Severity.ERROR,
      fix="Give the kind of type the call takes: a message to publishers and subscriptions, "
          "the service itself (`Trigger`, not `Trigger.Request`) to services and clients")
def interface_of_another_kind(package: Package) -> Iterator[Hit]:
    """A publisher, subscription, service, client or action is given another kind of type.

    ## What it does
    Reports the type argument of `create_publisher` and `create_subscription` when it is a
    service or action class (`Trigger`), of `create_service` and `create_client` when it is
    a message class or a service's `Request`/`Response` (`Trigger.Request`), and of rclpy's
    `ActionClient` and `ActionServer` when it is no action class: classes imported from a
    package's `.msg`, `.srv` or `.action` module (names bound only by that import); and any
    of them given a Python type (`bool`, `str`, `dict`; a name the module does not bind). A
    service's `Request` or an action's `Goal` is a message, which a publisher may send. An
    import naming an interface of a known package under another kind (`from std_msgs.srv
    import String`) is left to DEP008.

    ## Why is this bad?
    rclpy checks the type support when the entity is created and raises `RuntimeError: The
    service type provided is not valid (...), this might be a message or action` (or the
    message version): the node dies in its constructor (checked on Jazzy). A publisher given
    a message instead of its class (`create_publisher(String(), ...)`) is created, but every
    `publish()` raises `TypeError` (also reported).

    ## Example
    ```python
    self.client = self.create_client(Trigger.Request, 'trigger')
    ```

    ## Use instead
    ```python
    self.client = self.create_client(Trigger, 'trigger')
    ```
    """
    indexes = {module.path: index for module, _, index in installed_trees(package)}
    for path, value, api, parameter in _checked(package):
        if _instance_published(value, api, indexes[path], package.context.distro):
            yield Hit(Span(path, value.lineno, value.col_offset + 1),
                      f"`{api}` takes a message type but is given `{ast.unparse(value)}`, a "
                      f"message: rclpy creates the publisher, then every `publish()` raises "
                      f"TypeError (isinstance() arg 2 must be a type)",
                      f"Give the class: `{ast.unparse(value.func)}`")  # type: ignore
            continue
        builtin = _builtin_type(value, indexes[path])
        if builtin is not None:
            yield Hit(Span(path, value.lineno, value.col_offset + 1),
                      f"`{api}` takes {_WANTED[parameter]} but is given `{builtin}`, a Python "
                      "type: rclpy raises AttributeError (type object 'type' has no attribute "
                      "'_TYPE_SUPPORT') when it is created",
                      f"Use `std_msgs.msg.{_STD_MSGS[builtin]}`" if builtin in _STD_MSGS and
                      parameter == "msg_type" else None)
            continue
        qualified = indexes[path].qualified(value) if isinstance(
            value, (ast.Name, ast.Attribute)) else None
        given = _given(qualified, package.context.distro) if qualified else None
        if given is not None and given != _WANTED[parameter]:
            yield Hit(Span(path, value.lineno, value.col_offset + 1),
                      f"`{api}` takes {_WANTED[parameter]} but is given "
                      f"`{ast.unparse(value)}`, {given}: rclpy raises RuntimeError when it "
                      "is created")
