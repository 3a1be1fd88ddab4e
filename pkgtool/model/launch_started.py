"""Which node actions a Python launch file certainly starts, each time it is launched.

Read from ``generate_launch_description`` alone, and only from its straight-line statements:
the actions listed in the returned ``LaunchDescription([...])`` (or in lists of names assigned
once), and those added with ``ld.add_action(x)`` to the description the function returns. An
action under an ``if``, a loop, a ``try`` or another action (``GroupAction``, a timer, an
event handler), one with a ``condition=``, and every action of a function that may return
early are left out: any of those may not start, or may start in another namespace.
"""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.model.ast_nodes import descendants, last_name

_SIMPLE = (ast.Expr, ast.Assign, ast.AnnAssign, ast.Return, ast.Pass, ast.Import,
           ast.ImportFrom)
"""Statements that run straight through: anything else may skip or repeat what it holds."""
_NAMESPACE_KEYS = ("__ns", "__namespace")


def certainly_started(tree: ast.Module) -> frozenset[ast.Call]:
    """The node action calls of ``tree`` that start whenever its launch description runs."""
    function = next((s for s in tree.body if isinstance(s, ast.FunctionDef) and
                     s.name == "generate_launch_description"), None)
    if function is None or any(isinstance(n, ast.Return) for s in function.body
                               if not isinstance(s, _SIMPLE) for n in descendants(s)):
        return frozenset()
    straight = [s for s in function.body if isinstance(s, _SIMPLE)]
    assigned = _assigned_once(function, straight)
    returned = next((s.value for s in straight if isinstance(s, ast.Return)), None)
    description = _resolved(returned, assigned)
    if not (isinstance(description, ast.Call) and last_name(description.func) ==
            "LaunchDescription"):
        return frozenset()
    items = list(_listed(description.args[0] if description.args else None, assigned))
    if isinstance(returned, ast.Name):
        items.extend(item for s in straight for item in _added(s, returned.id, assigned))
    return frozenset(item for item in items if isinstance(item, ast.Call) and
                     not any(k.arg in ("condition", None) for k in item.keywords) and
                     not _sets_namespace(item))


def _assigned_once(function: ast.FunctionDef, straight: list[ast.stmt]
                   ) -> dict[str, ast.expr]:
    """Names bound once in the whole function, by a straight-line ``name = value``."""
    counts: dict[str, int] = {}
    for node in descendants(function):
        if isinstance(node, ast.Name) and not isinstance(node.ctx, ast.Load):
            counts[node.id] = counts.get(node.id, 0) + 1
        elif isinstance(node, (ast.Global, ast.Nonlocal)):
            counts.update({name: 2 for name in node.names})
    return {s.targets[0].id: s.value for s in straight
            if isinstance(s, ast.Assign) and len(s.targets) == 1 and
            isinstance(s.targets[0], ast.Name) and counts.get(s.targets[0].id) == 1}


def _resolved(node: ast.expr | None, assigned: dict[str, ast.expr]) -> ast.expr | None:
    for _ in range(len(assigned) + 1):
        if not isinstance(node, ast.Name):
            return node
        node = assigned.get(node.id)
    return None


def _listed(node: ast.expr | None, assigned: dict[str, ast.expr]) -> Iterator[ast.expr]:
    """The actions a list display (a name assigned one, a sum of such) certainly holds."""
    node = _resolved(node, assigned)
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
        yield from _listed(node.left, assigned)
        yield from _listed(node.right, assigned)
    elif isinstance(node, (ast.List, ast.Tuple)):
        for item in node.elts:
            found = _resolved(item, assigned)
            if found is not None and not isinstance(found, ast.Starred):
                yield found


def _added(statement: ast.stmt, description: str, assigned: dict[str, ast.expr]
           ) -> Iterator[ast.expr]:
    """The action ``description.add_action(x)`` adds, as a statement of its own."""
    call = statement.value if isinstance(statement, ast.Expr) else None
    if isinstance(call, ast.Call) and isinstance(call.func, ast.Attribute) and \
            call.func.attr == "add_action" and isinstance(call.func.value, ast.Name) and \
            call.func.value.id == description and len(call.args) == 1:
        found = _resolved(call.args[0], assigned)
        if found is not None:
            yield found


def _sets_namespace(call: ast.Call) -> bool:
    """True when a text in the call may remap the node's namespace (``-r __ns:=/robot``)."""
    return any(isinstance(n, ast.Constant) and isinstance(n.value, str) and
               any(key in n.value for key in _NAMESPACE_KEYS) for n in descendants(call))
