"""Which names a statement may change: what becomes opaque when it cannot be evaluated."""

from __future__ import annotations

import ast

from pkgtool.model.setup_eval.scope import Scope
from pkgtool.model.setup_eval.values import UserFunc


def changed_names(node: ast.AST, scope: Scope, seen: set[int] | None = None) -> set[str]:
    """Names ``node`` may rebind, or whose list/dict/set it may mutate (also via its calls).

    Immutable values (strings, modules, paths) cannot change through a method call or as an
    argument, and comprehension variables are local to the comprehension.
    """
    seen = set() if seen is None else seen
    local = {n.id for c in ast.walk(node) if isinstance(c, ast.comprehension)
             for n in ast.walk(c.target) if isinstance(n, ast.Name)}
    names: set[str] = set()
    for child in ast.walk(node):
        if isinstance(child, ast.Name) and isinstance(child.ctx, (ast.Store, ast.Del)):
            names.add(child.id)
        elif isinstance(child, (ast.Subscript, ast.Attribute)) and \
                isinstance(child.ctx, ast.Store):
            names.update(_mutable(_base_name(child), scope))
        elif isinstance(child, (ast.Import, ast.ImportFrom)):
            names.update((a.asname or a.name).split(".")[0] for a in child.names)
        elif isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            names.add(child.name)
        elif isinstance(child, ast.Call):
            names.update(_call_changes(child, scope, seen))
    return names - local


def _call_changes(node: ast.Call, scope: Scope, seen: set[int]) -> set[str]:
    """Containers a call may mutate: its receiver, its arguments, a function's globals."""
    names = _base_name(node.func) if isinstance(node.func, ast.Attribute) else []
    for argument in (*node.args, *(k.value for k in node.keywords)):
        if isinstance(argument, (ast.Name, ast.Starred)):
            names.extend(_base_name(argument))
    changed = set(_mutable(names, scope))
    function = _lookup(scope, node.func.id) if isinstance(node.func, ast.Name) else None
    if isinstance(function, UserFunc) and id(function.node) not in seen:
        seen.add(id(function.node))
        assigned = {n.id for n in ast.walk(function.node)
                    if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Store)}
        declared = {n for g in ast.walk(function.node) if isinstance(g, ast.Global)
                    for n in g.names}
        inner = Scope(function.scope)
        for statement in function.node.body:
            changed |= {n for n in changed_names(statement, inner, seen)
                        if n not in assigned or n in declared}
    return changed


def _lookup(scope: Scope, name: str) -> object:
    try:
        return scope.lookup(name)
    except KeyError:
        return None


def _mutable(names: list[str], scope: Scope) -> list[str]:
    return [n for n in names if isinstance(_lookup(scope, n), (list, dict, set))]


def _base_name(node: ast.AST) -> list[str]:
    while isinstance(node, (ast.Attribute, ast.Subscript, ast.Starred)):
        node = node.value
    return [node.id] if isinstance(node, ast.Name) else []
