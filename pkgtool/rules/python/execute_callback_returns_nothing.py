"""PYC038: an action's execute callback never returns the result."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._callbacks import execute_callbacks
from pkgtool.rules.registry import rule
from pkgtool.rules.scopes import returns_none


@rule("PYC038", "execute-callback-returns-nothing", Severity.ERROR,
      fix="End the execute callback with `return result` (a `<Action>.Result()`)")
def execute_callback_returns_nothing(package: Package) -> Iterator[Hit]:
    """An action server's execute callback never returns the result.

    ## What it does
    Reports the plain function (not `async`, no decorator) given to rclpy's `ActionServer` as
    its execute callback when it has no `return <value>` and no `yield`, like PYC026 for
    service callbacks.

    ## Why is this bad?
    rclpy stores what the callback returns as the goal's result: None fails there ("'NoneType'
    object has no attribute ..."), the goal never gets a result and the client's
    `get_result_async()` future never completes (checked on Jazzy).

    ## Example
    ```python
    def execute(self, goal_handle):
        goal_handle.succeed()
    ```

    ## Use instead
    ```python
    def execute(self, goal_handle):
        goal_handle.succeed()
        return Fibonacci.Result(sequence=[0, 1])
    ```
    """
    for path, value, function, _, _ in execute_callbacks(package):
        if returns_none(function):
            yield Hit(Span(path, function.lineno, function.col_offset + 1),
                      f"The execute callback `{function.name}` never returns the result: the "
                      "goal never gets one and the client waits forever",
                      related=(Span(path, value.lineno, value.col_offset + 1),))
