"""PYC035: a callback waits for a service response its own node would have to deliver."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import spin_cause
from pkgtool.rules.python._callbacks import callback_arguments
from pkgtool.rules.python._message_instances import callback_function, method_receiver
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index

_REGISTRATIONS = frozenset({"create_timer()", "create_subscription()", "create_service()"})
"""The rclpy calls whose callbacks the node's executor runs in the node's callback groups."""
_SPINS = frozenset({"rclpy.spin", "rclpy.spin_once", "rclpy.spin_until_future_complete"})


@rule("PYC035", "blocking-call-in-callback", Severity.ERROR,
      fix="Use `call_async()` with `add_done_callback()`, or give the client its own callback "
          "group and spin the node with a `MultiThreadedExecutor`")
def blocking_call_in_callback(package: Package) -> Iterator[Hit]:
    """A callback waits for a service response that its own node would have to deliver.

    ## What it does
    Looks at the methods a node class registers as timer, subscription or service callbacks
    (`self.create_timer(1.0, self.tick)`), neither registration nor client given a
    `callback_group`, and reports in them a synchronous `self.client.call(request)` on a client
    every assignment of which is `self.create_client(...)` without a `callback_group`, and
    `rclpy.spin_until_future_complete(self, future)` (or `rclpy.spin_once(self)`,
    `rclpy.spin(self)`): spinning the node from inside one of its own callbacks. Nested
    functions and modules that change the node's default callback group are not judged.

    ## Why is this bad?
    The response reaches the client through the node's executor, in the client's callback
    group. Without callback groups the client and the running callback share the node's
    default, mutually exclusive group, so the executor never delivers the response while the
    callback waits: `call()` blocks forever (or returns None at its timeout) with any executor,
    and spinning the node again from its own callback returns only at its timeout with no
    result (checked on Jazzy). The node stops doing anything else meanwhile.

    ## Example
    ```python
    def tick(self):
        response = self.client.call(Trigger.Request())
    ```

    ## Use instead
    ```python
    def tick(self):
        future = self.client.call_async(Trigger.Request())
        future.add_done_callback(self.on_response)
    ```
    """
    for path, value, api, _, index, tree in callback_arguments(package):
        found = callback_function(value, tree, index) if api in _REGISTRATIONS else None
        registration = _call_of(value, index)
        if found is None or found[1] != 1 or registration is None or _grouped(registration) \
                or any(a.attr == "_default_callback_group" for a in index.attributes):
            continue
        method, receiver = found[0], method_receiver(found[0])
        clients = _ungrouped_clients(index.enclosing_class(method), receiver)
        for call in index.calls:
            if index.enclosing_function(call) is not method or receiver is None:
                continue
            where = Span(path, call.lineno, call.col_offset + 1)
            if _spins_itself(call, receiver, index):
                yield Hit(where,
                          f"`{ast.unparse(call.func)}({receiver}, ...)` spins the node inside "
                          f"its own callback `{method.name}`: the response it waits for is "
                          "never delivered (it returns at its timeout, if any, with no result)",
                          related=(Span(path, value.lineno, value.col_offset + 1),),
                          cause=spin_cause(where))
            elif _calls_client(call, receiver, clients):
                yield Hit(where,
                          f"`{ast.unparse(call.func)}()` waits in the callback `{method.name}` "
                          "for a response the node's executor cannot deliver until the callback "
                          "returns: it blocks forever (both are in the node's default callback "
                          "group)", related=(Span(path, value.lineno, value.col_offset + 1),))


def _call_of(value: ast.expr, index: Index) -> ast.Call | None:
    """The call ``value`` is an argument of (directly or as a keyword's value)."""
    parent = index.parents.get(id(value))
    if isinstance(parent, ast.keyword):
        parent = index.parents.get(id(parent))
    return parent if isinstance(parent, ast.Call) else None


def _grouped(call: ast.Call) -> bool:
    """True when the call gives a callback group (``create_timer`` takes it third)."""
    timer = isinstance(call.func, ast.Attribute) and call.func.attr == "create_timer"
    return any(k.arg in ("callback_group", None) for k in call.keywords) or \
        (timer and len(call.args) > 2) or any(isinstance(a, ast.Starred) for a in call.args)


def _ungrouped_clients(cls: ast.ClassDef | None, receiver: str | None) -> frozenset[str]:
    """Attributes of ``receiver`` every assignment of which in ``cls`` is a
    ``create_client()`` call without a callback group."""
    if cls is None or receiver is None:
        return frozenset()
    values: dict[str, list[ast.expr]] = {}
    for node in ast.walk(cls):
        targets = node.targets if isinstance(node, ast.Assign) else \
            [node.target] if isinstance(node, (ast.AnnAssign, ast.AugAssign)) else []
        for target in targets:
            if isinstance(target, ast.Attribute):
                values.setdefault(target.attr, []).append(
                    node.value if isinstance(node, ast.Assign) else target)
    return frozenset(name for name, assigned in values.items() if all(
        isinstance(v, ast.Call) and isinstance(v.func, ast.Attribute) and
        v.func.attr == "create_client" and ast.unparse(v.func.value) == receiver
        and not _grouped(v) for v in assigned))


def _spins_itself(call: ast.Call, receiver: str, index: Index) -> bool:
    """``rclpy.spin_until_future_complete(self, ...)`` and the like."""
    first = call.args[0] if call.args else next(
        (k.value for k in call.keywords if k.arg == "node"), None)
    return index.qualified(call.func) in _SPINS and isinstance(first, ast.Name) and \
        first.id == receiver


def _calls_client(call: ast.Call, receiver: str, clients: frozenset[str]) -> bool:
    """``self.client.call(...)`` on one of the ``clients``."""
    func = call.func
    return isinstance(func, ast.Attribute) and func.attr == "call" and \
        isinstance(func.value, ast.Attribute) and func.value.attr in clients and \
        isinstance(func.value.value, ast.Name) and func.value.value.id == receiver
