"""PYC036: the result of an rclpy future is read right after the request is sent."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import child_nodes
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import FUNCTIONS, installed_trees

_SENDS = frozenset({"call_async", "send_goal_async", "get_result_async", "cancel_goal_async"})
"""rclpy methods that send a request and return a future its response completes later."""
_SIMPLE = (ast.Assign, ast.AnnAssign, ast.AugAssign, ast.Expr, ast.Return)


@rule("PYC036", "future-result-too-early", Severity.ERROR,
      fix="Wait for the future first (`rclpy.spin_until_future_complete(node, future)` outside "
          "callbacks), or read it in `future.add_done_callback(...)`")
def future_result_too_early(package: Package) -> Iterator[Hit]:
    """The result of an rclpy future is read right after the request is sent.

    ## What it does
    In modules that import rclpy, reports `.result()` taken on the future of
    `client.call_async(request)` (or `send_goal_async`, `get_result_async`,
    `cancel_goal_async`) by the very next statement, or on the call itself
    (`client.call_async(request).result()`), with nothing in between that could let the
    response arrive: no spin, no `await`, no wait. `async` functions are not judged.

    ## Why is this bad?
    `call_async()` only sends the request; the response arrives later, when an executor
    spins the node. Until then `future.result()` is `None`, so the next line fails with
    `AttributeError: 'NoneType' object has no attribute ...` or works on nothing (checked on
    Jazzy).

    ## Example
    ```python
    future = self.client.call_async(request)
    response = future.result()
    ```

    ## Use instead
    ```python
    future = self.client.call_async(request)
    future.add_done_callback(self.on_response)
    ```
    """
    for module, tree, index in installed_trees(package):
        if not any(i.top_level == "rclpy" for i in module.imports):
            continue
        for call in index.calls:
            if _is_result(call) and _sends(call.func.value):  # type: ignore[attr-defined]
                yield _hit(module.path, call)
        for function in index.functions:
            if isinstance(function, FUNCTIONS[0]):
                yield from (_hit(module.path, c) for c in _next_statement_results(function))


def _hit(path: str, call: ast.Call) -> Hit:
    return Hit(Span(path, call.lineno, call.col_offset + 1),
               f"`{ast.unparse(call)}` is read before the response can arrive: the future is not "
               "done yet, so it gives None")


def _is_result(call: ast.Call) -> bool:
    return isinstance(call.func, ast.Attribute) and call.func.attr == "result" and \
        not call.args and not call.keywords


def _sends(node: ast.expr) -> bool:
    """True for ``x.call_async(...)`` and the other sending calls."""
    return isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and \
        node.func.attr in _SENDS


def _next_statement_results(function: ast.FunctionDef) -> Iterator[ast.Call]:
    """``future.result()`` calls in the simple statement right after ``future = x.call_async()``
    in the same block (of ``function``, not of functions nested in it)."""
    for block in _blocks(function):
        for sent, following in zip(block, block[1:]):
            if not (isinstance(sent, ast.Assign) and len(sent.targets) == 1 and
                    _sends(sent.value) and isinstance(following, _SIMPLE)):
                continue
            future = ast.unparse(sent.targets[0])
            calls = [n for n in _run_now(following) if isinstance(n, ast.Call)]
            results = [c for c in calls if _is_result(c) and
                       ast.unparse(c.func.value) == future]  # type: ignore[attr-defined]
            if results and not any(_may_wait(c, future) for c in calls if c not in results):
                yield results[0]


def _run_now(statement: ast.stmt) -> Iterator[ast.AST]:
    """The nodes of ``statement`` in source order, but not those of its lambdas (a done
    callback's body runs once the future is done)."""
    pending: list[ast.AST] = [statement]
    while pending:
        node = pending.pop()
        if not isinstance(node, ast.Lambda):
            yield node
            pending.extend(reversed(child_nodes(node)))


def _may_wait(call: ast.Call, future: str) -> bool:
    """True for a call that might let the response arrive: one given the future, or named
    like a wait (``spin``, ``wait``, ``sleep``)."""
    name = ast.unparse(call.func).lower()
    return any(word in name for word in ("spin", "wait", "sleep")) or any(
        ast.unparse(a) == future for a in (*call.args, *(k.value for k in call.keywords)))


def _blocks(function: ast.FunctionDef) -> Iterator[list[ast.stmt]]:
    """The statement lists of ``function`` outside nested functions and classes."""
    pending: list[ast.AST] = [function]
    while pending:
        node = pending.pop()
        for name in ("body", "orelse", "finalbody"):
            block = getattr(node, name, None)
            if isinstance(block, list) and block and isinstance(block[0], ast.stmt):
                yield block
                pending.extend(s for s in block
                               if not isinstance(s, (*FUNCTIONS, ast.ClassDef)))
        pending.extend(getattr(node, "handlers", []))
