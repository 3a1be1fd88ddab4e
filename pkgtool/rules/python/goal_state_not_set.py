"""PYC037: an action's execute callback never says how the goal ended."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._callbacks import execute_callbacks
from pkgtool.rules.registry import rule

_SETTERS = frozenset({"succeed", "abort", "canceled"})
"""The goal handle's methods that set the goal's final state."""
_READS = frozenset({"request", "publish_feedback", "is_cancel_requested", "is_active",
                    "goal_id", "status", "is_executing"})
"""The goal handle's members that leave its state alone."""


@rule("PYC037", "goal-state-not-set", Severity.ERROR,
      fix="Call `goal_handle.succeed()` (or `abort()`, `canceled()`) before returning the result")
def goal_state_not_set(package: Package) -> Iterator[Hit]:
    """An action server's execute callback never calls `succeed()`, `abort()` or `canceled()`.

    ## What it does
    Looks at the function given to rclpy's `ActionServer` as its execute callback when it
    never calls `goal_handle.succeed()`, and reports each `return <result>` that a path
    reaches without `abort()` or `canceled()` either (`goal_handle.request`,
    `publish_feedback()` and `is_cancel_requested` leave the state alone). A callback that
    calls `succeed()` somewhere, or passes its goal handle on, stores it or uses it in any
    other way, is not judged: leaving a goal to rclpy's implicit abort may be meant there.

    ## Why is this bad?
    When the callback returns with the goal still executing, rclpy logs "Goal state not set,
    assuming aborted" and the client receives the result with the status ABORTED (checked on
    Jazzy): a client that checks the status, as `ros2 action send_goal` and Nav2 do, treats
    every goal as failed though the work was done.

    ## Example
    ```python
    def execute(self, goal_handle):
        result = Fibonacci.Result(sequence=[0, 1])
        return result
    ```

    ## Use instead
    ```python
    def execute(self, goal_handle):
        result = Fibonacci.Result(sequence=[0, 1])
        goal_handle.succeed()
        return result
    ```
    """
    for path, value, function, handle, index in execute_callbacks(package):
        uses = [node for node in ast.walk(function)
                if isinstance(node, ast.Name) and node.id == handle]
        if not all(_known_use(node, index.parents.get(id(node))) for node in uses) or \
                any(index.parents[id(node)].attr == "succeed" for node in uses):  # type: ignore
            continue
        for returned in _unsettled_returns(function.body, handle):
            yield Hit(Span(path, returned.lineno, returned.col_offset + 1),
                      f"The execute callback `{function.name}` returns here without calling "
                      f"`{handle}.succeed()`, `abort()` or `canceled()`: rclpy then aborts the "
                      "goal, whatever the result", related=(
                          Span(path, value.lineno, value.col_offset + 1),))


SETTLES, NEVER, UNKNOWN = "settles", "never", "unknown"
"""How the paths through a statement that go on to the next one leave the goal's state:
all set it, none does, or some do."""


def _known_use(name: ast.Name, parent: ast.AST | None) -> bool:
    """True when this use of the goal handle reads it or sets its state."""
    return isinstance(parent, ast.Attribute) and parent.value is name and \
        parent.attr in _READS | _SETTERS and not isinstance(parent.ctx, (ast.Store, ast.Del))


def _sets(node: ast.AST, handle: str) -> bool:
    """True when ``node`` holds a call of one of the handle's setters."""
    return any(isinstance(n, ast.Call) and isinstance(n.func, ast.Attribute) and
               n.func.attr in _SETTERS and isinstance(n.func.value, ast.Name) and
               n.func.value.id == handle for n in ast.walk(node))


def _exits(block: list[ast.stmt]) -> bool:
    """True when the block never goes on to what follows it (it ends in a jump)."""
    return bool(block) and isinstance(block[-1], (ast.Return, ast.Raise, ast.Continue,
                                                  ast.Break))


def _sequence(block: list[ast.stmt], handle: str) -> str:
    """How the block's paths that reach its end leave the goal's state."""
    state = NEVER
    for statement in block:
        found = _statement(statement, handle)
        if found == SETTLES:
            return SETTLES
        if found == UNKNOWN:
            state = UNKNOWN
    return state


def _statement(statement: ast.stmt, handle: str) -> str:
    if isinstance(statement, ast.If):
        going_on = [b for b in (statement.body, statement.orelse) if not _exits(b)]
        states = {_sequence(b, handle) for b in going_on}
        return states.pop() if len(states) == 1 else UNKNOWN if states else SETTLES
    if isinstance(statement, (ast.For, ast.While, ast.AsyncFor)):
        inner = _sequence(statement.body, handle) if not _exits(statement.body) else NEVER
        return NEVER if inner == NEVER and not _sets(ast.Module(statement.orelse, []), handle) \
            else UNKNOWN
    if isinstance(statement, (ast.With, ast.AsyncWith)):
        return _sequence(statement.body, handle)
    if isinstance(statement, (ast.Expr, ast.Assign, ast.AnnAssign, ast.AugAssign)):
        return SETTLES if _sets(statement, handle) else NEVER
    return UNKNOWN if _sets(statement, handle) else NEVER


def _unsettled_returns(block: list[ast.stmt], handle: str, before: str = NEVER
                       ) -> Iterator[ast.Return]:
    """``return <value>`` statements reached by paths none of which set the goal's state
    (``before``: how the paths into ``block`` left it)."""
    state = before
    for statement in block:
        if state == SETTLES:
            return
        if isinstance(statement, ast.Return) and statement.value is not None and state == NEVER:
            yield statement
        for inner in _inner_blocks(statement):
            settled = isinstance(statement, ast.If) and _ended_in(statement, handle) is inner
            yield from _unsettled_returns(inner, handle, SETTLES if settled else state)
        found = _statement(statement, handle)
        state = SETTLES if found == SETTLES else UNKNOWN if UNKNOWN in (state, found) else NEVER


def _ended_in(statement: ast.If, handle: str) -> list[ast.stmt] | None:
    """The branch of ``if not goal_handle.is_active:`` (its body; of ``if
    goal_handle.is_active:``, its ``else``) that runs only once the goal's state is final
    (canceled or aborted elsewhere): rclpy leaves a goal that is not active alone."""
    test, negated = statement.test, False
    if isinstance(test, ast.UnaryOp) and isinstance(test.op, ast.Not):
        test, negated = test.operand, True
    if isinstance(test, ast.Attribute) and test.attr == "is_active" and \
            isinstance(test.value, ast.Name) and test.value.id == handle:
        return statement.body if negated else statement.orelse
    return None


def _inner_blocks(statement: ast.stmt) -> list[list[ast.stmt]]:
    """The statement lists a compound statement runs right away (not nested functions)."""
    if isinstance(statement, (ast.If, ast.For, ast.While, ast.AsyncFor)):
        return [statement.body, statement.orelse]
    if isinstance(statement, (ast.With, ast.AsyncWith)):
        return [statement.body]
    return []
