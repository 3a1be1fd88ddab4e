"""PYC013: a callback of rclpy's API given as the result of calling it (`self.cb()`)."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._callbacks import callback_arguments
from pkgtool.rules.python._own_callees import missing_parameter, own_definition, own_method
from pkgtool.rules.scopes import returns_none
from pkgtool.rules.registry import rule


@rule("PYC013", "callback-called", Severity.ERROR,
      fix="Pass the function itself, without parentheses: `self.create_timer(1.0, self.tick)`")
def callback_called(package: Package) -> Iterator[Hit]:
    """A callback of rclpy's API is the result of calling the function, not the function.

    ## What it does
    Reports callback arguments of rclpy calls (`create_timer`, `create_subscription`,
    `create_service`, `create_guard_condition`, `add_on_set_parameters_callback` and the pre-
    and post-set ones, `send_goal_async`'s `feedback_callback`, `add_done_callback`, and
    `ActionServer`'s `execute_callback`, `goal_callback`, `handle_accepted_callback` and
    `cancel_callback`), positional or keyword, that call a method of the same class
    (`self.tick()`) or a function of the module (`tick()`) whose definition returns no value:
    no `return <value>`, no `yield`, not `async`, no decorator, not a placeholder body;
    whatever it returns, when the call leaves out a parameter the function requires
    (`self.execute()` for `def execute(self, goal_handle)`). A call of a factory that returns
    a callback, `functools.partial(...)` or a lambda is fine.

    ## Why is this bad?
    The function runs once while the node is set up, and rclpy gets its result, `None`, as
    the callback. A timer then dies when it first fires with `TypeError: 'NoneType' object
    is not callable`; a subscription fails at once with `RuntimeError:
    Subscription.__init__(): callback should be either be callable with one argument(to get
    only the message) or two (to get message and message info)`.

    ## Example
    ```python
    self.timer = self.create_timer(0.5, self.publish())
    ```

    ## Use instead
    ```python
    self.timer = self.create_timer(0.5, self.publish)
    ```
    """
    for path, value, api, _, index, tree in callback_arguments(package):
        if not isinstance(value, ast.Call):
            continue
        method = own_method(value, index)
        target = method[0] if method else own_definition(value, index, tree)
        name = ast.unparse(value.func)
        missing = missing_parameter(value, target, 1 if method else 0) \
            if isinstance(target, ast.FunctionDef) else None
        if missing:
            yield Hit(Span(path, value.lineno, value.col_offset + 1),
                      f"`{ast.unparse(value)}` is called without its `{missing}` where `{api}` "
                      f"wants the callback: Python raises TypeError (missing argument) as the "
                      f"line runs; pass `{name}` without parentheses",
                      fix=f"Pass `{name}` without parentheses")
        elif isinstance(target, ast.FunctionDef) and returns_none(target):
            yield Hit(Span(path, value.lineno, value.col_offset + 1),
                      f"`{ast.unparse(value)}` is called and its result, None, is passed to "
                      f"`{api}` as the callback: pass `{name}` without parentheses",
                      fix=f"Pass `{name}` without parentheses")
