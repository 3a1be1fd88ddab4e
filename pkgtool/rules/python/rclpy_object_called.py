"""PYC075: an rclpy object that is not callable (a publisher, a client, a timer) is called."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity, shortened
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._rclpy_objects import object_class, table_class
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import installed_trees

_INSTEAD = {"rclpy.publisher.Publisher": "publish",
            "rclpy.client.Client": "call_async",
            "rclpy.action.client.ActionClient": "send_goal_async",
            "rclpy.timer.Rate": "sleep",
            "rclpy.task.Future": "result",
            "rclpy.clock.ROSClock": "now",
            "rclpy.parameter.Parameter": "value"}
"""The method (or property) meant, for the classes where one is the likely intent."""
_NOT_CALLABLE = frozenset({*_INSTEAD, "rclpy.subscription.Subscription", "rclpy.timer.Timer",
                           "rclpy.service.Service", "rclpy.action.server.ActionServer",
                           "rclpy.action.client.ClientGoalHandle", "rclpy.time.Time",
                           "rclpy.duration.Duration"})
"""rclpy classes without ``__call__`` (Humble to Rolling)."""


@rule("PYC075", "rclpy-object-called", Severity.ERROR,
      fix="Call the object's method: `self.publisher.publish(msg)`")
def rclpy_object_called(package: Package) -> Iterator[Hit]:
    """Installed code calls an rclpy object that is not callable.

    ## What it does
    Reports a call of an object whose rclpy class is certain (as PYC004 knows it: what a
    node's `create_publisher()`, `create_subscription()`, `create_timer()`,
    `create_rate()`, `create_client()`, `create_service()`, `get_clock()`,
    `declare_parameter()` or `get_parameter()` return, an action client or server, a future,
    a goal handle, a time or a duration) when that class has no `__call__`:
    `self.publisher_(msg)` meant `self.publisher_.publish(msg)`, `self.client(request)`
    meant `self.client.call_async(request)`, `self.get_parameter('rate')()` meant `.value`.

    ## Why is this bad?
    The call raises `TypeError: 'Publisher' object is not callable` when it runs, mostly in
    a callback: the node logs the error and stops doing its job.

    ## Example
    ```python
    self.publisher_ = self.create_publisher(String, 'chatter', 10)
    self.publisher_(String(data='hello'))
    ```

    ## Use instead
    ```python
    self.publisher_ = self.create_publisher(String, 'chatter', 10)
    self.publisher_.publish(String(data='hello'))
    ```
    """
    for module, tree, index in installed_trees(package):
        for call in index.calls:
            func = call.func
            if not isinstance(func, (ast.Name, ast.Attribute, ast.Call)):
                continue
            cls = object_class(func, package, tree, index)
            table = table_class(cls) if cls else None
            if table not in _NOT_CALLABLE:
                continue
            shown = shortened(ast.unparse(func))
            meant = _INSTEAD.get(table or "")
            fix = f"Use `{shown}.{meant}`" if meant else None
            yield Hit(Span(module.path, call.lineno, call.col_offset + 1),
                      f"`{shown}` is an rclpy `{(cls or '').rsplit('.', 1)[-1]}`, which is not "
                      "callable: calling it raises TypeError", fix)
