"""PYC026: a service, action execute or set-parameters callback that never returns its
result."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._callbacks import callback_arguments
from pkgtool.rules.python._message_instances import callback_function
from pkgtool.rules.python._value_types import certain_type
from pkgtool.rules.registry import rule
from pkgtool.rules.scopes import returns_none, scope_walk
from pkgtool.rules.syntax_trees import Index


_RETURNED = {
    ("create_service()", "callback"): (
        "service callback", "the response",
        "rclpy's send_response() raises TypeError on the first request",
        "End the callback with `return response`"),
    ("ActionServer()", "execute_callback"): (
        "action execute callback", "the result",
        "the client never gets the goal's result", "End the callback with `return result`, "
        "the action's `Result()`"),
    ("add_on_set_parameters_callback()", "callback"): (
        "set-parameters callback", "a `SetParametersResult`",
        "rclpy rejects every parameter change ('Callback returned an invalid type')",
        "End the callback with `return SetParametersResult(successful=True)`"),
}
"""The callbacks whose value rclpy uses, by API and parameter: what they are called, what
they must return, what returning None does, how to fix it."""
_STOPS = (ast.Return, ast.Raise, ast.While, ast.Try, ast.With, ast.AsyncWith, ast.Match)
"""Statements after which the end of a body may not be reached (or not only by falling)."""
_PLAIN_ENDS = (ast.Expr, ast.Assign, ast.AugAssign, ast.AnnAssign)


def _classes_returned(function: ast.FunctionDef | ast.AsyncFunctionDef, package: Package,
                      tree: ast.Module, index: Index) -> Iterator[ast.expr]:
    """The values of ``return`` statements of ``function`` (not of functions inside it) that
    are an imported interface class itself (``return AddTwoInts.Response``)."""
    for node in scope_walk(function.body):
        if isinstance(node, ast.Return) and isinstance(node.value, (ast.Name, ast.Attribute)) \
                and certain_type(node.value, package, tree, index) == "type":
            yield node.value


def _falls_off_the_end(function: ast.FunctionDef | ast.AsyncFunctionDef) -> bool:
    """True for a plain ``def`` (no decorator but ``staticmethod``/``classmethod``, no
    ``yield``) whose body certainly can end without a ``return``: no top-level statement of
    it returns, raises, loops with ``while`` or enters ``try``/``with``/``match``, and the
    last one is an expression or assignment (not a call of an ``exit``)."""
    last = function.body[-1]
    if not isinstance(function, ast.FunctionDef) or any(
            not (isinstance(d, ast.Name) and d.id in ("staticmethod", "classmethod"))
            for d in function.decorator_list) or \
            any(isinstance(s, _STOPS) for s in function.body) or \
            not isinstance(last, _PLAIN_ENDS) or isinstance(last, ast.Expr) and (
                isinstance(last.value, ast.Constant) or "exit" in ast.unparse(last.value)):
        return False
    return not any(isinstance(n, (ast.Yield, ast.YieldFrom)) for n in scope_walk(function.body))


@rule("PYC026", "service-callback-returns-nothing", Severity.ERROR,
      fix="End the callback with `return response`")
def service_callback_returns_nothing(package: Package) -> Iterator[Hit]:
    """A service, action execute or set-parameters callback never returns its result.

    ## What it does
    Reports the callback given to `create_service`, the `execute_callback` of an rclpy
    `ActionServer` and the callback given to `add_on_set_parameters_callback`, when it is a
    plain method of the registering class (`self.on_request`) or a plain function bound once
    in the module, and certainly returns `None`: no `return <value>` anywhere, no `yield`,
    not `async`, no decorator, not a placeholder body (only `pass`, `...`, a docstring or
    `raise`). Also reports such a callback that returns a value on some paths but certainly
    can fall off its end: no statement of its body (outside nested blocks) returns, raises,
    loops with `while` or enters `try`, `with` or `match`, and the last one is an
    expression or assignment (`self.get_logger().info('done')` after an early `return`).
    And one that returns an imported interface class itself instead of an instance
    (`return AddTwoInts.Response`), which rclpy refuses as it refuses `None`.

    ## Why is this bad?
    rclpy sends what the callback returns as the response: `None` makes
    `Service.send_response` raise `TypeError` in the executor on the first request, the
    node dies and the client waits forever. Filling in the `response` argument is not
    enough: it must be returned. An action server whose execute callback returns `None`
    never answers the client's result request (checked on Jazzy), and a set-parameters
    callback must return a `SetParametersResult`: with `None`, rclpy rejects every change
    (`ros2 param set` fails).

    ## Example
    ```python
    def on_request(self, request, response):
        response.success = True
    ```

    ## Use instead
    ```python
    def on_request(self, request, response):
        response.success = True
        return response
    ```
    """
    for path, value, api, parameter, index, tree in callback_arguments(package):
        kind = _RETURNED.get((api, parameter))
        found = callback_function(value, tree, index) if kind else None
        if kind is None or found is None:
            continue
        what, returned, effect, fix = kind
        function = found[0]
        if returns_none(function):
            yield Hit(Span(path, function.lineno, function.col_offset + 1),
                      f"The {what} `{ast.unparse(value)}` never returns {returned}: {effect}",
                      fix, related=(Span(path, value.lineno, value.col_offset + 1),))
            continue
        for returned_class in _classes_returned(function, package, tree, index):
            name = ast.unparse(returned_class)
            yield Hit(Span(path, returned_class.lineno, returned_class.col_offset + 1),
                      f"The {what} `{ast.unparse(value)}` returns the class `{name}`, not "
                      f"{returned}: {effect}", f"Return an instance: `{name}()`, or the one "
                      "rclpy passes in",
                      related=(Span(path, value.lineno, value.col_offset + 1),))
        if _falls_off_the_end(function):
            end = function.body[-1]
            yield Hit(Span(path, end.lineno, end.col_offset + 1),
                      f"The {what} `{ast.unparse(value)}` returns {returned} on some paths but "
                      f"ends here without a `return`: when it gets here, {effect}",
                      fix, related=(Span(path, value.lineno, value.col_offset + 1),))
