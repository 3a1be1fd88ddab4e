"""Walking one function scope of a syntax tree: its nodes and the names it binds."""

from __future__ import annotations

import ast
from collections import Counter
from collections.abc import Iterator

from pkgtool.model.ast_nodes import child_nodes
from pkgtool.model.memo import per_tree

COMPREHENSIONS = (ast.ListComp, ast.SetComp, ast.DictComp, ast.GeneratorExp)
NESTED_SCOPES = frozenset({ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef, ast.Lambda,
                           *COMPREHENSIONS})
"""The classes of the nodes opening a scope of their own (tested with ``type(node) in``: a
parsed tree holds no subclass of them)."""
_BROAD = frozenset({"Exception", "BaseException"})
_NAME_ERRORS = _BROAD | {"NameError", "UnboundLocalError"}
ALWAYS = 1 << 30
"""Binding count of names declared ``global``/``nonlocal``: never equal to a real count."""
Scope = ast.Module | ast.ClassDef | ast.FunctionDef | ast.AsyncFunctionDef
BINDERS = frozenset({ast.Name, ast.arg, ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef,
                     ast.Import, ast.ImportFrom, ast.ExceptHandler, ast.MatchAs, ast.MatchStar,
                     ast.MatchMapping, ast.Global, ast.Nonlocal})
"""The classes of the nodes that may bind a name (a parsed tree holds no subclass of them):
``type(node) in BINDERS`` lets the other nodes, most of them, skip every binding test."""


def caught_names(handler: ast.ExceptHandler) -> set[str]:
    """The names of the exceptions ``handler`` catches (``BaseException`` for a bare
    ``except:``)."""
    if handler.type is None:
        return {"BaseException"}
    types = handler.type.elts if isinstance(handler.type, ast.Tuple) else [handler.type]
    return {t.id if isinstance(t, ast.Name) else t.attr for t in types
            if isinstance(t, (ast.Name, ast.Attribute))}


def catches_everything(handler: ast.ExceptHandler) -> bool:
    """``except:``, ``except Exception:`` or ``except BaseException:`` (also in a tuple)."""
    return bool(caught_names(handler) & _BROAD)


def catches_name_error(handler: ast.ExceptHandler) -> bool:
    """``except NameError:`` (or ``UnboundLocalError``, or anything broader)."""
    return bool(caught_names(handler) & _NAME_ERRORS)


def scope_walk(body: list[ast.stmt], *, skip_protected: bool = False) -> Iterator[ast.AST]:
    """Nodes of ``body`` in this scope: nested functions, classes and comprehensions are
    yielded but not entered. With ``skip_protected``, the bodies of ``try`` blocks that
    catch NameError (or anything broader) are skipped too."""
    stack: list[ast.AST] = list(reversed(body))
    while stack:
        node = stack.pop()
        yield node
        if type(node) in NESTED_SCOPES:
            continue
        if skip_protected and isinstance(node, ast.Try) and any(
                catches_name_error(h) for h in node.handlers):
            children: list[ast.AST] = [*node.handlers, *node.orelse, *node.finalbody]
        else:
            children = child_nodes(node)
        children.reverse()
        stack += children


def own_scope(node: ast.AST, parents: dict[int, ast.AST]) -> tuple[ast.AST | None, ast.AST]:
    """The innermost function, class, lambda or comprehension around ``node`` (None at module
    level), with the node below it on the way up (``node``'s statement in its body...):
    ``node`` is among what :func:`scope_walk` yields for that scope when it is there."""
    child, parent = node, parents.get(id(node))
    while parent is not None and type(parent) not in NESTED_SCOPES:
        child, parent = parent, parents.get(id(parent))
    return parent, child


def bound_names(where: ast.stmt | list[ast.stmt] | ast.FunctionDef | ast.AsyncFunctionDef
                ) -> Counter[str]:
    """How many times each name is bound in ``where`` (parameters included for a function)."""
    found: Counter[str] = Counter()
    if isinstance(where, (ast.FunctionDef, ast.AsyncFunctionDef)):
        arguments = where.args
        for arg in (*arguments.posonlyargs, *arguments.args, *arguments.kwonlyargs,
                    arguments.vararg, arguments.kwarg):
            if arg is not None:
                found[arg.arg] += 1
        body = where.body
    else:
        body = where if isinstance(where, list) else [where]
    for node in scope_walk(body):
        if type(node) not in BINDERS:
            continue
        if isinstance(node, ast.Name) and not isinstance(node.ctx, ast.Load):
            found[node.id] += 1
        elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            found[node.name] += 1
        elif isinstance(node, (ast.Import, ast.ImportFrom)):
            found.update((a.asname or a.name).split(".")[0] for a in node.names)
        elif isinstance(node, ast.ExceptHandler) and node.name:
            found[node.name] += 1
        elif isinstance(node, (ast.MatchAs, ast.MatchStar)) and node.name:
            found[node.name] += 1
        elif isinstance(node, (ast.Global, ast.Nonlocal)):
            for name in node.names:
                found[name] = ALWAYS
    return found


@per_tree
def scope_bindings(scope: Scope) -> Counter[str]:
    """:func:`bound_names` of a function (its parameters included) or of the body of a module
    or class, computed once per scope (several rules ask about the same); treat as read-only."""
    return bound_names(scope if isinstance(scope, (ast.FunctionDef, ast.AsyncFunctionDef))
                       else scope.body)


def single_assignments(where: ast.AST) -> dict[str, ast.expr]:
    """Names bound exactly once in ``where`` (a function with its nested scopes, or a whole
    module), by ``name = value``, with their value: no other binding of the name anywhere in
    it (an assignment, a parameter, a ``def``, ``class`` or import, ``global``)."""
    counts: dict[str, int] = {}
    values: dict[str, ast.expr] = {}
    for node in ast.walk(where):
        for name, weight in _bound_here(node):
            counts[name] = counts.get(name, 0) + weight
        if isinstance(node, ast.Assign) and len(node.targets) == 1 and \
                isinstance(node.targets[0], ast.Name):
            values[node.targets[0].id] = node.value
    return {name: value for name, value in values.items() if counts.get(name) == 1}


def _bound_here(node: ast.AST) -> list[tuple[str, int]]:
    """The names ``node`` binds, each with how much it counts (2: never a plain one)."""
    if isinstance(node, ast.Name):
        return [] if isinstance(node.ctx, ast.Load) else [(node.id, 1)]
    if isinstance(node, ast.arg):
        return [(node.arg, 2)]
    if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
        return [(node.name, 2)]
    if isinstance(node, (ast.Import, ast.ImportFrom)):
        return [(alias.asname or alias.name.split(".")[0], 2) for alias in node.names]
    if isinstance(node, (ast.Global, ast.Nonlocal)):
        return [(name, 2) for name in node.names]
    return []


_PLAIN_DECORATORS = frozenset({"staticmethod", "classmethod"})


def plainly_decorated(function: ast.FunctionDef | ast.AsyncFunctionDef) -> bool:
    """True when ``function`` has no decorator but ``staticmethod`` or ``classmethod`` (none
    that may change what calling it gives)."""
    return all(isinstance(d, ast.Name) and d.id in _PLAIN_DECORATORS
               for d in function.decorator_list)


def _stub(function: ast.FunctionDef) -> bool:
    """A body of only a docstring, ``pass``, ``...`` and ``raise``: a placeholder to override."""
    return all(isinstance(s, (ast.Pass, ast.Raise)) or isinstance(s, ast.Expr) and
               isinstance(s.value, ast.Constant) for s in function.body)


def returns_none(function: ast.FunctionDef | ast.AsyncFunctionDef) -> bool:
    """True when calling ``function`` certainly gives None: a plain ``def`` (no decorator but
    ``staticmethod``/``classmethod``, no stub) with no ``return <value>`` and no ``yield``."""
    if not isinstance(function, ast.FunctionDef) or _stub(function) or \
            not plainly_decorated(function):
        return False
    for node in scope_walk(function.body):
        if isinstance(node, (ast.Yield, ast.YieldFrom)):
            return False
        if isinstance(node, ast.Return) and node.value is not None and not (
                isinstance(node.value, ast.Constant) and node.value.value is None):
            return False
    return True
