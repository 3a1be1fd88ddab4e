"""PYC077: a method of an rclpy object called with arguments its parameters cannot take."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity, shortened
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._rclpy_objects import (ACTION_CLIENT, CLOCK, FUTURE, GOAL_FUTURE,
                                                 GOAL_HANDLE, NODE, object_class)
from pkgtool.rules.node_api import derives_from_node_alone
from pkgtool.rules.python._assignments import assigned_values, is_none
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, installed_trees

_FUTURE_METHODS = {"result": ((), 0), "done": ((), 0), "cancel": ((), 0),
                   "add_done_callback": (("callback",), 1), "set_result": (("result",), 1)}
_METHODS: dict[str, dict[str, tuple[tuple[str, ...], int]]] = {
    "rclpy.client.Client": {"call_async": (("request",), 1),
                            "call": (("request", "timeout_sec"), 1),
                            "wait_for_service": (("timeout_sec",), 0),
                            "service_is_ready": ((), 0)},
    "rclpy.publisher.Publisher": {"get_subscription_count": ((), 0)},
    NODE: {"destroy_node": ((), 0), "get_logger": ((), 0), "get_clock": ((), 0),
           "get_name": ((), 0), "get_namespace": ((), 0)},
    "rclpy.timer.Timer": {"cancel": ((), 0), "reset": ((), 0), "is_canceled": ((), 0)},
    FUTURE: _FUTURE_METHODS, GOAL_FUTURE: _FUTURE_METHODS,
    ACTION_CLIENT: {"send_goal_async": (("goal", "feedback_callback", "goal_uuid"), 1),
                    "wait_for_server": (("timeout_sec",), 0), "server_is_ready": ((), 0)},
    GOAL_HANDLE: {"get_result_async": ((), 0), "cancel_goal_async": ((), 0)},
    CLOCK: {"now": ((), 0)},
}
"""rclpy class -> method -> (its parameters after ``self``, how many of them it requires), the
same from Humble to Rolling but for ``Client.call``'s ``timeout_sec`` (Iron and newer).
``Publisher.publish`` is PYC020's."""
_NAMES = frozenset(name for methods in _METHODS.values() for name in methods)


def _problem(call: ast.Call, parameters: tuple[str, ...], required: int) -> str | None:
    """What Python's TypeError would say, in our words; None when the arguments bind."""
    if len(call.args) > len(parameters):
        takes = f"takes {len(parameters)}" if parameters else "takes none"
        return f"it gives {len(call.args)} positional argument" \
            f"{'s' * (len(call.args) != 1)} where the method {takes}"
    given = {k.arg for k in call.keywords}
    missing = [p for p in parameters[len(call.args):required] if p not in given]
    return f"it leaves out `{missing[0]}`, which the method requires" if missing else None


@rule("PYC077", "rclpy-method-arguments", Severity.ERROR,
      fix="Pass what the method takes (see the message)")
def rclpy_method_arguments(package: Package) -> Iterator[Hit]:
    """A method of an rclpy object is called with arguments its parameters cannot take.

    ## What it does
    Reports calls of the common methods of objects whose rclpy class is certain (as PYC004
    works it out: what `create_client()`, `create_publisher()`, `create_timer()`,
    `call_async()`, an `ActionClient` or `get_clock()` make, and `self` in a class deriving
    from `Node` alone, or a local name bound to an instance of such a class of the module)
    that give more positional arguments than the method takes, or leave
    out one it requires: `client.call_async()`, `client.call_async(request, 5.0)`,
    `self.destroy_node(self)`, `future.result(1.0)` (`publisher.publish()` is PYC020's). A
    module that defines a method of the same name (an override), and calls passing `*args`
    or `**kwargs`, are left alone; keywords the method lacks are PYC029's.

    ## Why is this bad?
    Python raises TypeError when the line runs, usually inside a callback or at shutdown:
    the request is never sent, the node is never destroyed cleanly.

    ## Example
    ```python
    future = self.client.call_async()
    self.destroy_node(self)
    ```

    ## Use instead
    ```python
    future = self.client.call_async(Trigger.Request())
    self.destroy_node()
    ```
    """
    for module, tree, index in installed_trees(package):
        for call in index.calls:
            func = call.func
            if not isinstance(func, ast.Attribute) or func.attr not in _NAMES or \
                    any(isinstance(a, ast.Starred) for a in call.args) or \
                    any(k.arg is None for k in call.keywords) or \
                    index.defines_function(func.attr):
                continue
            cls = object_class(func.value, package, tree, index, depth=1) or \
                _own_node(func.value, package, tree, index)
            known = _METHODS.get(cls or "", {}).get(func.attr)
            problem = _problem(call, *known) if known else None
            if problem is not None:
                assert cls is not None
                owner = cls.rsplit(".", 1)[-1].split("<")[0]
                yield Hit(Span(module.path, call.lineno, call.col_offset + 1),
                          f"`{shortened(ast.unparse(call))}` cannot call rclpy's "
                          f"`{owner}.{func.attr}`: {problem}, Python raises TypeError")


def _own_node(value: ast.expr, package: Package, tree: ast.Module, index: Index) -> str | None:
    """:data:`NODE` for a local name every assignment of which makes an instance of a class
    of the module deriving from rclpy's Node alone (``node = Talker()``): it has Node's
    methods (the module overrides none of the one called, as the caller checks)."""
    assigned = assigned_values(value, package, tree, index) \
        if isinstance(value, ast.Name) else None
    classes = {c.name: c for c in tree.body if isinstance(c, ast.ClassDef)}
    made = [v for v, _ in assigned or () if not is_none(v)]
    return NODE if made and all(
        isinstance(v, ast.Call) and isinstance(v.func, ast.Name) and v.func.id in classes and
        derives_from_node_alone(classes[v.func.id], index) for v in made) else None
