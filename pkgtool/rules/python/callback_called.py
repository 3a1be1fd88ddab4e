"""PYC013: a callback of rclpy's API given as the result of calling it (`self.cb()`)."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import subtree
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._callbacks import callback_arguments
from pkgtool.rules.scopes import bound_names, returns_none, scope_bindings
from pkgtool.rules.syntax_trees import FUNCTIONS, Index
from pkgtool.rules.registry import rule


def _functions_around(node: ast.AST, index: Index) -> list[ast.FunctionDef | ast.AsyncFunctionDef]:
    """The functions around ``node``, innermost first (up to its class or the module)."""
    found = []
    function = index.enclosing_function(node)
    while function is not None:
        found.append(function)
        function = index.enclosing_function(function)
    return found


def _defined_once(body: list[ast.stmt], name: str) -> ast.FunctionDef | None:
    """The ``def name`` of ``body``, when nothing else there binds ``name``."""
    defs = [s for s in body if isinstance(s, FUNCTIONS) and s.name == name]
    if len(defs) != 1 or bound_names(body)[name] != 1 or not isinstance(defs[0], ast.FunctionDef):
        return None
    return defs[0]


def _method(call: ast.Call, index: Index) -> ast.FunctionDef | None:
    """The method ``self.name()`` calls, found in the caller's class, when nothing rebinds it."""
    func = call.func
    cls = index.enclosing_class(call)
    outer = _functions_around(call, index)[-1:] if cls is not None else []
    if not outer or not isinstance(func, ast.Attribute) or not isinstance(func.value, ast.Name) \
            or index.parents.get(id(outer[0])) is not cls or outer[0].decorator_list:
        return None
    positional = [*outer[0].args.posonlyargs, *outer[0].args.args]
    if not positional or positional[0].arg != func.value.id:
        return None
    assigned = any(isinstance(n, ast.Attribute) and n.attr == func.attr and
                   not isinstance(n.ctx, ast.Load) for n in subtree(cls))
    return None if assigned else _defined_once(cls.body, func.attr)


def _function(call: ast.Call, index: Index, tree: ast.Module) -> ast.FunctionDef | None:
    """The module-level function ``name()`` calls, when no scope around the call rebinds it."""
    func = call.func
    if not isinstance(func, ast.Name) or any(
            scope_bindings(f)[func.id] for f in _functions_around(call, index)):
        return None
    cls = index.enclosing_class(call)
    if cls is not None and scope_bindings(cls)[func.id]:
        return None
    return _defined_once(tree.body, func.id)


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
        method = _method(value, index)
        target = method or _function(value, index, tree)
        name = ast.unparse(value.func)
        missing = _missing(value, target, 1 if method else 0) if target is not None else None
        if missing:
            yield Hit(Span(path, value.lineno, value.col_offset + 1),
                      f"`{ast.unparse(value)}` is called without its `{missing}` where `{api}` "
                      f"wants the callback: Python raises TypeError (missing argument) as the "
                      f"line runs; pass `{name}` without parentheses",
                      fix=f"Pass `{name}` without parentheses")
        elif target is not None and returns_none(target):
            yield Hit(Span(path, value.lineno, value.col_offset + 1),
                      f"`{ast.unparse(value)}` is called and its result, None, is passed to "
                      f"`{api}` as the callback: pass `{name}` without parentheses",
                      fix=f"Pass `{name}` without parentheses")


def _missing(call: ast.Call, function: ast.FunctionDef, skipped: int) -> str | None:
    """The first required parameter of ``function`` that ``call`` gives no value for (after
    the ``skipped`` receiver), when the call passes no ``*args``/``**kwargs``."""
    if any(isinstance(a, ast.Starred) for a in call.args) or \
            any(k.arg is None for k in call.keywords):
        return None
    arguments = function.args
    positional = [*arguments.posonlyargs, *arguments.args][skipped:]
    required = positional[:len(positional) - len(arguments.defaults)]
    given = {k.arg for k in call.keywords}
    return next((a.arg for a in required[len(call.args):] if a.arg not in given), None)
