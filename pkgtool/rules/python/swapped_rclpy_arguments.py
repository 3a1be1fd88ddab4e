"""PYC030: rclpy's create_* methods given their arguments in another order (ROS 1's)."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import (INTERFACE, PARAMETERS, literal_type, node_api_calls,
                                    unpacks)
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, installed_trees

KINDS = {"msg_type": "message", "srv_type": "service"}
_SERVED = frozenset({"create_subscription", "create_service"})
"""The creators whose third argument is the callback."""


def _method_of_class(value: ast.expr, call: ast.Call, index: Index) -> bool:
    """True for a lambda, or ``self.<a method of the class around the call>``."""
    if isinstance(value, ast.Lambda):
        return True
    around = index.enclosing_class(call)
    return around is not None and isinstance(value, ast.Attribute) and \
        isinstance(value.value, ast.Name) and value.value.id == "self" and any(
            isinstance(f, (ast.FunctionDef, ast.AsyncFunctionDef)) and f.name == value.attr
            for f in around.body)


def swapped_argument(call: ast.Call, method: str, index: Index) -> tuple[ast.expr, str] | None:
    """The misplaced argument of ``call`` and what is wrong, or None."""
    first = call.args[0] if call.args else None
    second = call.args[1] if len(call.args) > 1 else None
    if method == "create_timer":
        return (first, "the callback is given where the period goes (the period comes "
                "first)") if first is not None and _method_of_class(first, call, index) else None
    kind = KINDS[PARAMETERS[method][0]]
    if first is not None and literal_type(first) == "str":
        return first, (f"a string is given where the {kind} type goes (the type comes "
                       "first, then the name: ROS 1 had them the other way round)")
    if second is not None and INTERFACE.fullmatch(index.qualified(second) or ""):
        return second, (f"the {kind} type is given where the name goes (the type comes "
                        "first: ROS 1 had them the other way round)")
    if method in _SERVED and second is not None and _method_of_class(second, call, index):
        return second, ("the callback is given where the name goes (the type comes first, "
                        "then the name, then the callback)")
    return None


@rule("PYC030", "swapped-rclpy-arguments", Severity.ERROR,
      fix="Pass the type first, then the name: `create_publisher(String, 'chatter', 10)`")
def swapped_rclpy_arguments(package: Package) -> Iterator[Hit]:
    """A publisher, subscription, service, client or timer is created with its arguments in
    the wrong order.

    ## What it does
    Reports `create_publisher`, `create_subscription`, `create_service` and `create_client`
    calls whose first positional argument is a string (`'chatter'`) or whose second is a
    message or service class imported from a `.msg`/`.srv` module (the topic and the type
    swapped, as ROS 1's `rospy.Publisher('chatter', String)` had them), `create_subscription`
    and `create_service` calls whose second is a lambda or a method of the class (the
    callback where the name goes), and `create_timer` calls whose first argument is one (the
    callback where the period goes). Only modules importing rclpy are looked at, not calls
    with `*args` or `**kwargs`, and not when the package defines a function of the same name.

    ## Why is this bad?
    rclpy checks the type: a string raises (`'str' object has no attribute
    '_TYPE_SUPPORT'`), and `create_timer` converts its first argument with `float()`,
    which raises `TypeError` for a method. The node dies at start-up.

    ## Example
    ```python
    self.publisher = self.create_publisher('chatter', String, 10)
    self.timer = self.create_timer(self.publish, 0.5)
    ```

    ## Use instead
    ```python
    self.publisher = self.create_publisher(String, 'chatter', 10)
    self.timer = self.create_timer(0.5, self.publish)
    ```
    """
    defined = {function.name for _, _, index in installed_trees(package)
               for function in index.functions}
    methods = {*PARAMETERS, "create_timer"} - defined
    for module, call, method, index in node_api_calls(package, methods):
        found = None if unpacks(call) else swapped_argument(call, method, index)
        if found:
            yield Hit(Span(module.path, found[0].lineno, found[0].col_offset + 1),
                      f"`{method}()` has its arguments out of order: {found[1]}; rclpy raises "
                      "at start-up")
