"""PYC003: ``finally``/``except`` code uses a name that only the ``try`` body assigns."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._try_bindings import (fails_before, harmless, in_loop, inspecting,
                                                none_before, statements_before, tested_names,
                                                uses)
from pkgtool.rules.registry import rule
from pkgtool.rules.scopes import bound_names, catches_everything, scope_bindings
from pkgtool.rules.syntax_trees import Index, installed_trees


def _unbound_uses(index: Index, node: ast.Try) -> Iterator[tuple[ast.Name, str, int]]:
    places = [node.finalbody] + [h.body for h in node.handlers if catches_everything(h)]
    function = index.enclosing_function(node)
    if function is None or not any(places) or in_loop(index, node, function):
        return
    if id(function) in inspecting(index):
        return
    everywhere = scope_bindings(function)
    for name, count in bound_names(node.body).items():
        if count != everywhere.get(name) or not fails_before(node.body, name):
            continue
        use = next((u for body in places for u in uses(body, name)
                    if not _guarded_by_earlier(u, name, node, index, everywhere) and
                    not _guarded_by_later(u, name, node, index, function) and
                    not _after_a_failing_read(u, body, name, node, everywhere)), None)
        if use is not None:
            yield use, name, next(s.lineno for s in node.body if name in bound_names([s]))


def _guarded_by_earlier(use: ast.Name, name: str, node: ast.Try, index: Index,
                        everywhere: dict[str, int]) -> bool:
    """True when ``use`` runs only under ``if guard:`` (or ``if guard is not None:``) for a
    name ``guard`` that is ``None`` before the ``try`` and bound once in its body, with only
    statements that cannot raise from there to the binding of ``name`` (``executor = X()``,
    then ``pending = None``): when the guard holds, ``name`` is bound."""
    bound_at = next(i for i, s in enumerate(node.body) if name in bound_names([s]))
    child, parent = use, index.parents.get(id(use))
    while parent is not None and parent is not node:
        if isinstance(parent, ast.If) and any(child is s for s in parent.body):
            for guard in tested_names(parent.test):
                at = [i for i, s in enumerate(node.body) if guard in bound_names([s])]
                if len(at) == 1 and at[0] < bound_at and everywhere.get(guard) == 2 and \
                        bound_names(node.body)[guard] == 1 and \
                        none_before(guard, node, index) and \
                        all(harmless(s) for s in node.body[at[0] + 1:bound_at + 1]):
                    return True
        child, parent = parent, index.parents.get(id(parent))
    return False


def _guarded_by_later(use: ast.Name, name: str, node: ast.Try, index: Index,
                      function: ast.AST) -> bool:
    """True when ``use`` runs only under ``if guard:`` (or ``if guard is not None:``), for a
    name or ``self.x`` that is falsy when the ``try`` starts (``guard = None``, or ``if
    guard: return`` before it) and that the ``try`` body sets once, after binding ``name``,
    with nothing else setting it from the ``try`` to ``use`` (``self.sock = s`` after ``s =
    socket.socket()``): when the guard holds, ``name`` is bound."""
    bound_at = next(i for i, s in enumerate(node.body) if name in bound_names([s]))
    child, parent = use, index.parents.get(id(use))
    while parent is not None and parent is not node:
        if isinstance(parent, ast.If) and any(child is s for s in parent.body):
            for guard in tested_names(parent.test):
                sets = [i for i, s in enumerate(node.body) if _sets(s, guard)]
                others = [s for s in ast.walk(function) if isinstance(s, ast.stmt) and
                          not hasattr(s, "body") and node.lineno <= s.lineno <= use.lineno
                          and _sets(s, guard) and not any(s is b for b in node.body)]
                if len(sets) == 1 and sets[0] > bound_at and not others and \
                        _falsy_before(guard, node, index):
                    return True
        child, parent = parent, index.parents.get(id(parent))
    return False


def _sets(statement: ast.stmt, guard: str) -> bool:
    """True when ``statement`` (or one inside it) sets ``guard``: a name bound any way, or
    ``self.x`` assigned."""
    if "." not in guard and guard in bound_names([statement]):
        return True
    return any(isinstance(s, ast.Assign) and any(ast.unparse(t) == guard for t in s.targets) or
               isinstance(s, (ast.AugAssign, ast.AnnAssign)) and ast.unparse(s.target) == guard
               for s in ast.walk(statement))


def _falsy_before(guard: str, node: ast.Try, index: Index) -> bool:
    """True when the last statement before ``node`` in its block that sets or tests ``guard``
    is ``guard = None`` or ``if guard: return`` (or raise), without ``else``."""
    for statement in reversed(statements_before(node, index)):
        if isinstance(statement, ast.If) and not statement.orelse and \
                not isinstance(statement.test, ast.BoolOp) and \
                guard in tested_names(statement.test) and \
                isinstance(statement.body[-1], (ast.Return, ast.Raise)):
            return True  # `if a and b: return` leaves `a` truthy when `b` is not
        if _sets(statement, guard):
            return isinstance(statement, ast.Assign) and \
                isinstance(statement.value, ast.Constant) and statement.value.value is None
    return False


_CONDITIONAL = (ast.Lambda, ast.IfExp, ast.BoolOp, ast.ListComp, ast.SetComp, ast.DictComp,
                ast.GeneratorExp)
"""Expressions whose parts may not run."""


def _after_a_failing_read(use: ast.Name, body: list[ast.stmt], name: str, node: ast.Try,
                          everywhere: dict[str, int]) -> bool:
    """True when an earlier simple statement of ``body`` certainly reads a name the ``try``
    body alone binds, no earlier than ``name``: ``use`` runs only when that read did not
    fail, so the ``try`` got past ``name``'s binding (``logger.log(sim)`` then ``if
    energy:``, ``energy`` bound before ``sim``); that read is the one reported."""
    bound = bound_names(node.body)
    order = {key: next(i for i, s in enumerate(node.body) if key in bound_names([s]))
             for key in bound}
    for statement in body:
        if any(n is use for n in ast.walk(statement)):
            return False
        if isinstance(statement, (ast.Expr, ast.Assign)) and any(
                _bound_no_earlier(order[read], order[name], node.body) and
                bound[read] == everywhere.get(read)
                for read in _certain_reads(statement.value) if read in order):
            return True
    return False


def _bound_no_earlier(later: int, earlier: int, body: list[ast.stmt]) -> bool:
    """True when the statement ``later`` of ``body`` comes after ``earlier``, or is that one
    when it is a plain assignment (``sim, ctrl = make()``: both or neither)."""
    return later > earlier or later == earlier and isinstance(body[earlier], ast.Assign)


def _certain_reads(value: ast.expr) -> Iterator[str]:
    """The names ``value`` reads whatever happens (not in a lambda, a branch, a ``and``/``or``
    operand or a comprehension)."""
    found = [value]
    for current in found:
        if isinstance(current, ast.Name) and isinstance(current.ctx, ast.Load):
            yield current.id
        elif not isinstance(current, _CONDITIONAL):
            found.extend(ast.iter_child_nodes(current))


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
    there to the name's binding (`executor = Pool()` then `pending = None`), or binds
    `guard` after the name, `guard` (a name or `self.x`) being `None` before the `try` or
    ruled out by an `if guard: return` (`self.sock = s` after `s = socket.socket()`); nor a
    use after a statement of the block that reads a name the `try` binds no earlier
    (`logger.log(sim)`, then `if energy:` with `energy` bound before `sim`): only that first
    read can fail.

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
