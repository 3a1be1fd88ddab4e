"""PYC057: ``rclpy.shutdown()`` where straight-line code before it has already shut ROS down."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import EXITS, enclosing, last_name, nodes_of_class
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import INITS, SHUTDOWNS, TRY_SHUTDOWNS
from pkgtool.rules.python._reaching import preceding_statements
from pkgtool.rules.registry import rule
from pkgtool.rules.scopes import single_assignments
from pkgtool.rules.syntax_trees import Index, installed_trees

_ENDS = SHUTDOWNS | TRY_SHUTDOWNS


def _statement_call(statement: ast.stmt, names: frozenset[str], index: Index
                    ) -> ast.Call | None:
    """The call when ``statement`` is an expression calling one of ``names``."""
    call = statement.value if isinstance(statement, ast.Expr) else None
    if isinstance(call, ast.Call) and isinstance(call.func, (ast.Name, ast.Attribute)) and \
            index.qualified(call.func) in names:
        return call
    return None


def _called(statement: ast.stmt, names: frozenset[str], index: Index) -> ast.Call | None:
    """The call when ``statement`` is a bare call of one of ``names`` on the default context
    (no arguments)."""
    call = _statement_call(statement, names, index)
    return call if call is not None and not call.args and not call.keywords else None


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


_SPIN = frozenset({"rclpy.spin"})


def _callback_shutdown(index: Index, spin: ast.Call, spinner: ast.AST | None
                       ) -> ast.Call | None:
    """A bare ``rclpy.shutdown()`` in a method (not a finalizer, not ``spinner``, the function
    spinning) of the class whose instance ``spin`` (``rclpy.spin(node)``) spins, after which
    nothing in its method may leave the program (a ``raise``, ``sys.exit()``) or call
    ``rclpy.init()``: a callback ending the node (``rclpy.spin`` then returns)."""
    spun = _spun_class(spin, index, spinner)
    for call in index.calls if spun is not None else ():
        statement = index.parents.get(id(call))
        method = index.enclosing_function(call)
        if not (isinstance(statement, ast.Expr) and _called(statement, SHUTDOWNS, index) is call
                and method is not None and method is not spinner and method.name != "__del__"
                and index.enclosing_class(call) is spun):
            continue
        if not any(_leaves_or_restarts(after, index)
                   for after in _statements_after(statement, method, index)):
            return call
    return None


def _leaves_or_restarts(statement: ast.stmt, index: Index) -> bool:
    """True when ``statement`` (or a statement in it) raises, exits the program or calls
    ``rclpy.init()``."""
    return _initialises(statement, index) or any(
        isinstance(node, ast.Raise) or isinstance(node, ast.Call) and
        last_name(node.func) in EXITS for node in ast.walk(statement))


def _spun_class(spin: ast.Call, index: Index, spinner: ast.AST | None) -> ast.ClassDef | None:
    """The class of the module whose instance ``rclpy.spin(...)`` spins: a call of it, or a
    name ``spinner`` binds once to one."""
    node = spin.args[0] if spin.args else None
    if isinstance(node, ast.Name) and spinner is not None:
        node = single_assignments(spinner).get(node.id)  # type: ignore[arg-type]
    name = node.func.id if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) \
        else None
    return next((c for c in index.classes if c.name == name), None)


def _statements_after(statement: ast.stmt, method: ast.AST, index: Index) -> list[ast.stmt]:
    """The statements that may run after ``statement`` in ``method``: those after it in its
    block, then those after each block holding it, up to the method's body."""
    found: list[ast.stmt] = []
    current: ast.AST = statement
    while current is not method:
        holder = index.parents.get(id(current))
        if holder is None:
            break
        for name in ("body", "orelse", "finalbody"):
            block = getattr(holder, name, None)
            if isinstance(block, list) and any(s is current for s in block):
                place = next(i for i, s in enumerate(block) if s is current)
                found.extend(block[place + 1:])
        current = holder
    return found


def _after_spin(path: str, call: ast.Call, stopper: ast.Call, index: Index) -> Hit:
    function = index.enclosing_function(stopper)
    cls = index.enclosing_class(stopper)
    where = f"{cls.name}.{function.name}" if cls and function else "a method"
    return Hit(Span(path, call.lineno, call.col_offset + 1),
               f"`rclpy.shutdown()` runs after `rclpy.spin()` returned, which it does once ROS "
               f"is shut down, as `{where}` (line {stopper.lineno}) does: rclpy raises "
               "RuntimeError (Context must be initialized before it can be shutdown)")


@rule("PYC057", "rclpy-shut-down-twice", Severity.ERROR,
      fix="Call `rclpy.try_shutdown()` where ROS may already be shut down, or drop the second "
          "call")
def rclpy_shut_down_twice(package: Package) -> Iterator[Hit]:
    """`rclpy.shutdown()` runs after ROS was certainly shut down.

    ## What it does
    Reports a bare `rclpy.shutdown()` (the default context: no arguments) when a statement
    that always runs just before it in straight-line code already shut ROS down: an
    `rclpy.shutdown()` or `rclpy.try_shutdown()` call, or a `try` whose `finally` block makes
    one, with no `rclpy.init()` in between; or a bare `rclpy.spin(...)` earlier in the same
    block when a method of a class of the module (a callback; not `__del__`) calls
    `rclpy.shutdown()` (and does not raise or exit later in its block): `spin` returns only once
    ROS is shut down. Branches, loops and handlers are never assumed to have run: `except:
    rclpy.shutdown()` followed by `finally: rclpy.shutdown()` is left alone.

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
                spin = _statement_call(before, _SPIN, index) \
                    if index.parents.get(id(before)) is index.parents.get(id(statement)) else None
                stopper = _callback_shutdown(index, spin, index.enclosing_function(call)) \
                    if spin is not None else None
                if stopper is not None:
                    yield _after_spin(module.path, call, stopper, index)
                    break
                earlier = _shut_down_by(before, index)
                if earlier is not None:
                    name = index.qualified(earlier.func)  # type: ignore[arg-type]
                    yield Hit(Span(module.path, call.lineno, call.col_offset + 1),
                              f"`rclpy.shutdown()` runs after `{name}()` (line "
                              f"{earlier.lineno}) has shut ROS down: rclpy raises RuntimeError "
                              "(Context must be initialized before it can be shutdown)")
                    break
