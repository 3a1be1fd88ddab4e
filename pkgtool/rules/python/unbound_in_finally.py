"""PYC003: ``finally``/``except`` code uses a name that only the ``try`` body assigns."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.memo import per_tree
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.scopes import (bound_names, catches_everything, catches_name_error,
                                  own_scope, scope_bindings, scope_walk)
from pkgtool.rules.syntax_trees import Index, installed_trees
from pkgtool.rules.registry import rule

_LOOPS = (ast.For, ast.AsyncFor, ast.While)


def _harmless(statement: ast.stmt) -> bool:
    """Statements that cannot raise: ``pass`` and assignments of literals or names."""
    if isinstance(statement, ast.Pass):
        return True
    value = statement.value if isinstance(statement, (ast.Assign, ast.AnnAssign)) else None
    return value is not None and all(
        isinstance(n, (ast.Constant, ast.Name, ast.List, ast.Tuple, ast.Dict, ast.Set, ast.Load))
        for n in ast.walk(value))


def _fails_before(body: list[ast.stmt], name: str) -> bool:
    """True when a statement of ``body`` that may raise runs before ``name`` is bound."""
    for statement in body:
        if name in bound_names(statement):
            return not _harmless(statement)
        if not _harmless(statement):
            return True
    return False


def _uses(body: list[ast.stmt], name: str) -> Iterator[ast.Name]:
    """Reads of ``name`` in ``body``, except inside ``try`` blocks that catch NameError, and
    in the ``else`` of one whose body reads the bare name (``try: name / except NameError:
    ... / else: use(name)``: the ``else`` runs only when the name is bound)."""
    tested: set[int] = set()
    for node in scope_walk(body, skip_protected=True):
        if isinstance(node, ast.Try) and any(
                catches_name_error(h) for h in node.handlers) and any(
                isinstance(s, ast.Expr) and isinstance(s.value, ast.Name) and
                s.value.id == name for s in node.body):
            tested.update(id(n) for statement in node.orelse for n in ast.walk(statement))
        elif isinstance(node, ast.Name) and node.id == name and \
                isinstance(node.ctx, ast.Load) and id(node) not in tested:
            yield node


def _unbound_uses(index: Index, node: ast.Try) -> Iterator[tuple[ast.Name, str, int]]:
    places = [node.finalbody] + [h.body for h in node.handlers if catches_everything(h)]
    function = index.enclosing_function(node)
    if function is None or not any(places) or _in_loop(index, node, function):
        return
    if id(function) in _inspecting(index):
        return
    everywhere = scope_bindings(function)
    for name, count in bound_names(node.body).items():
        if count != everywhere.get(name) or not _fails_before(node.body, name):
            continue
        use = next((u for body in places for u in _uses(body, name)), None)
        if use is not None:
            yield use, name, next(s.lineno for s in node.body if name in bound_names(s))


def _in_loop(index: Index, node: ast.AST, function: ast.AST) -> bool:
    parent = index.parents.get(id(node))
    while parent is not None and parent is not function:
        if isinstance(parent, _LOOPS):
            return True
        parent = index.parents.get(id(parent))
    return False


@per_tree
def _inspecting(index: Index) -> set[int]:
    """Ids of the functions whose body (not a scope inside it) calls ``locals()``, ``vars()``
    or ``globals()``: they may inspect their own namespace."""
    found: set[int] = set()
    for call in index.calls:
        if isinstance(call.func, ast.Name) and call.func.id in ("locals", "vars", "globals"):
            scope, way = own_scope(call, index.parents)
            if isinstance(scope, (ast.FunctionDef, ast.AsyncFunctionDef)) and \
                    any(way is statement for statement in scope.body):
                found.add(id(scope))
    return found


@rule("PYC003", "unbound-in-finally", Severity.ERROR,
      fix="Assign the name (e.g. `node = None`) before `try` and check it before use")
def unbound_in_finally(package: Package) -> Iterator[Hit]:
    """A `finally` (or catch-all `except`) block uses a name assigned only inside the `try`.

    ## What it does
    In functions of installed modules, reports a read in `finally:` or in an `except:` /
    `except Exception:` block of a local name whose only assignments are in the `try` body,
    after a statement that can raise. `try` blocks inside loops, and uses guarded by
    `locals()` or a `try/except NameError` (or in the `else:` of one whose body reads the
    bare name), are not reported.

    ## Why is this bad?
    When the assignment fails (the node's constructor raises, Ctrl-C arrives first), the
    cleanup code raises `UnboundLocalError` and hides the real error behind a confusing
    traceback.

    ## Example
    ```python
    try:
        node = MyNode()
        rclpy.spin(node)
    finally:
        node.destroy_node()
    ```

    ## Use instead
    ```python
    node = None
    try:
        node = MyNode()
        rclpy.spin(node)
    finally:
        if node is not None:
            node.destroy_node()
    ```
    """
    for module, _, index in installed_trees(package):
        for node in index.tries:
            for use, name, line in _unbound_uses(index, node):
                yield Hit(Span(module.path, use.lineno, use.col_offset + 1),
                          f"`{name}` may be unbound here: it is only assigned inside the "
                          f"`try` block (line {line}), which can fail before that",
                          f"Assign `{name} = None` before `try` and check "
                          f"`if {name} is not None:` before using it")
