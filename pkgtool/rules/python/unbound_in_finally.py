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
        use = next((u for body in places for u in _uses(body, name)
                    if not _guarded_by_earlier(u, name, node, index, everywhere)), None)
        if use is not None:
            yield use, name, next(s.lineno for s in node.body if name in bound_names(s))


def _guarded_by_earlier(use: ast.Name, name: str, node: ast.Try, index: Index,
                        everywhere: dict[str, int]) -> bool:
    """True when ``use`` runs only under ``if guard:`` (or ``if guard is not None:``) for a
    name ``guard`` that is ``None`` before the ``try`` and bound once in its body, with only
    statements that cannot raise from there to the binding of ``name`` (``executor = X()``,
    then ``pending = None``): when the guard holds, ``name`` is bound."""
    bound_at = next(i for i, s in enumerate(node.body) if name in bound_names(s))
    child, parent = use, index.parents.get(id(use))
    while parent is not None and parent is not node:
        if isinstance(parent, ast.If) and any(child is s for s in parent.body):
            for guard in _tested_names(parent.test):
                at = [i for i, s in enumerate(node.body) if guard in bound_names(s)]
                if len(at) == 1 and at[0] < bound_at and everywhere.get(guard) == 2 and \
                        bound_names(node.body)[guard] == 1 and \
                        _none_before(guard, node, index) and \
                        all(_harmless(s) for s in node.body[at[0] + 1:bound_at + 1]):
                    return True
        child, parent = parent, index.parents.get(id(parent))
    return False


def _tested_names(test: ast.expr) -> Iterator[str]:
    """The names a test requires to be truthy or not None (``a``, ``a is not None``, and the
    parts of an ``and``)."""
    if isinstance(test, ast.BoolOp) and isinstance(test.op, ast.And):
        for value in test.values:
            yield from _tested_names(value)
    elif isinstance(test, ast.Name):
        yield test.id
    elif isinstance(test, ast.Compare) and isinstance(test.left, ast.Name) and \
            len(test.ops) == 1 and isinstance(test.ops[0], ast.IsNot) and \
            isinstance(test.comparators[0], ast.Constant) and test.comparators[0].value is None:
        yield test.left.id


def _none_before(guard: str, node: ast.Try, index: Index) -> bool:
    """True when a statement before ``node`` in its block is ``guard = None``."""
    parent = index.parents.get(id(node))
    for block in (getattr(parent, field, None) for field in ("body", "orelse", "finalbody")):
        if isinstance(block, list) and any(s is node for s in block):
            return any(isinstance(s, ast.Assign) and len(s.targets) == 1 and
                       isinstance(s.targets[0], ast.Name) and s.targets[0].id == guard and
                       isinstance(s.value, ast.Constant) and s.value.value is None
                       for s in block[:[id(b) for b in block].index(id(node))])
    return False


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
    bare name), are not reported; nor a use under `if guard:` where `guard = None`
    before the `try` and the `try` binds `guard` earlier, with nothing that can raise from
    there to the name's binding (`executor = Pool()` then `pending = None`).

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
