"""PYC057: ``rclpy.shutdown()`` where straight-line code before it has already shut ROS down."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import enclosing, nodes_of_class
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import INITS, SHUTDOWNS, TRY_SHUTDOWNS
from pkgtool.rules.python._reaching import preceding_statements
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, installed_trees

_ENDS = SHUTDOWNS | TRY_SHUTDOWNS


def _called(statement: ast.stmt, names: frozenset[str], index: Index) -> ast.Call | None:
    """The call when ``statement`` is a bare call of one of ``names`` on the default context
    (no arguments)."""
    call = statement.value if isinstance(statement, ast.Expr) else None
    if isinstance(call, ast.Call) and not call.args and not call.keywords and \
            isinstance(call.func, (ast.Name, ast.Attribute)) and \
            index.qualified(call.func) in names:
        return call
    return None


def _shut_down_by(statement: ast.stmt, index: Index) -> ast.Call | None:
    """The call by which ``statement`` certainly shuts ROS down: a bare shutdown call, or
    one at the top level of a ``finally`` block."""
    if isinstance(statement, (ast.Try, getattr(ast, "TryStar", ast.Try))):
        return next((c for s in statement.finalbody if (c := _called(s, _ENDS, index))), None)
    return _called(statement, _ENDS, index)


def _initialises(statement: ast.stmt, index: Index) -> bool:
    """True when ``statement`` calls ``rclpy.init`` anywhere within it."""
    return any(isinstance(c.func, (ast.Name, ast.Attribute)) and index.qualified(c.func) in INITS
               for c in nodes_of_class(statement, ast.Call))


@rule("PYC057", "rclpy-shut-down-twice", Severity.ERROR,
      fix="Call `rclpy.try_shutdown()` where ROS may already be shut down, or drop the second "
          "call")
def rclpy_shut_down_twice(package: Package) -> Iterator[Hit]:
    """`rclpy.shutdown()` runs after ROS was certainly shut down.

    ## What it does
    Reports a bare `rclpy.shutdown()` (the default context: no arguments) when a statement
    that always runs just before it in straight-line code already shut ROS down: an
    `rclpy.shutdown()` or `rclpy.try_shutdown()` call, or a `try` whose `finally` block makes
    one, with no `rclpy.init()` in between. Branches, loops and handlers are never assumed
    to have run: `except: rclpy.shutdown()` followed by `finally: rclpy.shutdown()` is left
    alone.

    ## Why is this bad?
    The second shutdown raises `RuntimeError: Context must be initialized before it can be
    shutdown`: the node ends with a traceback (and a non-zero exit code, which fails
    `launch_testing` and graders) after doing its work. `rclpy.try_shutdown()` is the call
    that does nothing when ROS is already shut down.

    ## Example
    ```python
    try:
        rclpy.spin(node)
    finally:
        node.destroy_node()
        rclpy.try_shutdown()
    rclpy.shutdown()
    ```

    ## Use instead
    ```python
    try:
        rclpy.spin(node)
    finally:
        node.destroy_node()
        rclpy.try_shutdown()
    ```
    """
    for module, tree, index in installed_trees(package):
        if not index.imports_from("rclpy"):
            continue
        for call in index.calls:
            statement = enclosing(call, index.parents, (ast.stmt,))
            if not isinstance(statement, ast.stmt) or \
                    _called(statement, SHUTDOWNS, index) is not call:
                continue
            for before in preceding_statements(statement, index):
                if _initialises(before, index):
                    break
                earlier = _shut_down_by(before, index)
                if earlier is not None:
                    name = index.qualified(earlier.func)  # type: ignore[arg-type]
                    yield Hit(Span(module.path, call.lineno, call.col_offset + 1),
                              f"`rclpy.shutdown()` runs after `{name}()` (line "
                              f"{earlier.lineno}) has shut ROS down: rclpy raises RuntimeError "
                              "(Context must be initialized before it can be shutdown)")
                    break
