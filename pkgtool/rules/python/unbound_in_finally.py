"""PYC003: ``finally``/``except`` code uses a name that only the ``try`` body assigns."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._try_bindings import (fails_before, harmless, in_loop, inspecting,
                                                none_before, tested_names, uses)
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
                    if not _guarded_by_earlier(u, name, node, index, everywhere)), None)
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
