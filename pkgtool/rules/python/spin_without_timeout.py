"""PYC005: ``spin_until_future_complete`` without a timeout in node code."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import descendants
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.syntax_trees import Index, installed_trees
from pkgtool.rules.node_api import spin_cause
from pkgtool.rules.python._message_instances import method_receiver
from pkgtool.rules.registry import rule

_NAME = "spin_until_future_complete"
REQUESTS = frozenset({"call_async", "send_goal_async", "cancel_goal_async"})
"""Calls whose future completes only when a server answers (not ``get_result_async``: an
accepted goal's result comes when the action ends, minutes later at times, and waiting for
it is the client's purpose)."""


def _is_request(node: ast.expr | None) -> bool:
    return (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)
            and node.func.attr in REQUESTS)


def _dotted(node: ast.expr) -> str | None:
    """``future`` or ``self._future`` for names and attribute chains, else None."""
    attrs: list[str] = []
    while isinstance(node, ast.Attribute):
        attrs.append(node.attr)
        node = node.value
    return ".".join([node.id, *reversed(attrs)]) if isinstance(node, ast.Name) else None


def _request_futures(scope: ast.AST) -> set[str]:
    """Names and attributes assigned a request's future in ``scope``."""
    return {name for node in descendants(scope) if isinstance(node, ast.Assign)
            and _is_request(node.value) for target in node.targets
            for name in [_dotted(target)] if name}


def _waited_future(call: ast.Call, index: Index) -> ast.expr | None:
    """The future a spin call waits for without a timeout, or None (timeout, not a spin; a
    misspelt ``timeout=`` is PYC029's TypeError)."""
    if any(isinstance(a, ast.Starred) for a in call.args) or any(
            k.arg in (None, "timeout_sec", "timeout") for k in call.keywords):
        return None
    keyword = next((k.value for k in call.keywords if k.arg == "future"), None)
    if index.qualified(call.func) == f"rclpy.{_NAME}" and len(call.args) < 3:  # 3rd: PYC033
        return keyword or (call.args[1] if len(call.args) > 1 else None)
    if (isinstance(call.func, ast.Attribute) and call.func.attr == _NAME
            and index.qualified(call.func) is None and len(call.args) < 2
            and not _on_own_receiver(call.func, index)):
        return keyword or (call.args[0] if call.args else None)
    return None


def _on_own_receiver(func: ast.Attribute, index: Index) -> bool:
    """True for ``self.spin_until_future_complete(...)`` in a method: the class's own method
    (a wrapper with its own timeout) or none at all (a node has none: PYC023's error)."""
    method = index.enclosing_function(func, through_lambdas=False)
    return isinstance(func.value, ast.Name) and method is not None and \
        index.enclosing_class(func) is not None and \
        method_receiver(method) == func.value.id


@rule("PYC005", "spin-without-timeout", Severity.WARNING,
      fix="Pass `timeout_sec=` and handle the future not being done")
def spin_without_timeout(package: Package) -> Iterator[Hit]:
    """Installed code waits for a future with no timeout.

    ## What it does
    Reports `rclpy.spin_until_future_complete(node, future)` and
    `executor.spin_until_future_complete(future)` calls in installed modules that pass no
    `timeout_sec` while waiting for a server's answer: a future from `call_async`,
    `send_goal_async` or `cancel_goal_async`. Spinning until some other future (a main loop
    that ends on a signal, an accepted goal's `get_result_async()`, which completes when the
    action ends, minutes later at times) and an explicit `timeout_sec=None` are taken as
    intended and not reported, nor is `self.spin_until_future_complete(...)` in a method:
    the class's own wrapper, or a method a node lacks (PYC023's AttributeError).

    ## Why is this bad?
    If the service or action server never answers (it crashed, its name is misspelled, the
    request was lost), the call blocks forever and the node hangs without a log line.

    ## Example
    ```python
    future = self.client.call_async(request)
    rclpy.spin_until_future_complete(self, future)
    ```

    ## Use instead
    ```python
    rclpy.spin_until_future_complete(self, future, timeout_sec=5.0)
    if not future.done():
        self.get_logger().error('service did not answer within 5 s')
    ```
    """
    for module, tree, index in installed_trees(package):
        attributes: set[str] | None = None
        for node in index.calls:
            future = _waited_future(node, index)
            if future is None:
                continue
            if not _is_request(future):
                if attributes is None:
                    attributes = {t for t in _request_futures(tree) if "." in t}
                function = index.enclosing_function(node)
                local = _request_futures(function) if function is not None else set()
                if _dotted(future) not in attributes | local:
                    continue
            where = Span(module.path, node.lineno, node.col_offset + 1)
            yield Hit(where, f"`{_NAME}` has no `timeout_sec`: it waits forever if the server "
                             "never answers", cause=spin_cause(where), consequence=True)
