"""What ran just before a statement, in straight-line code, and the one assignment whose value
a read of a local name there certainly sees.

``msg = String()`` then ``msg = 'hi'`` then ``pub.publish(msg)``: the bindings of ``msg``
disagree, yet the read sees the second. From the statement holding the read, the statements
before it in the same block are searched backwards for the nearest that stores the name; when
none does, the search goes on before the block's own statement (an ``if``, ``with``), but
never out of a loop (a later statement of its body reaches the read on the next turn, and a
``while`` test's read too), a ``try`` (whether its body ran is unknown) or a ``match``. The
nearest store counts when it is a plain ``name = value`` (or annotated) statement; a store
nested in another statement or an augmented one leaves the value unknown.
"""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.model.ast_nodes import enclosing
from pkgtool.rules.syntax_trees import Index

_BLOCKS = ("body", "orelse", "finalbody")
"""The statement lists of a compound statement (a ``with`` has ``body`` alone); within any of
them statements run in order."""
_THROUGH = (ast.If, ast.With, ast.AsyncWith)
"""Statements whose blocks run after what comes before them, once."""


def _position(node: ast.AST) -> tuple[int, int]:
    return node.lineno, node.col_offset  # type: ignore[attr-defined]


def _inside(store: ast.Name, statement: ast.stmt) -> bool:
    """True when ``store`` lies within ``statement``'s source span."""
    end = (statement.end_lineno or statement.lineno, statement.end_col_offset or 0)
    return _position(statement) <= _position(store) < end


def _before_in_block(statement: ast.stmt, parent: ast.AST) -> list[ast.stmt] | None:
    """The statements before ``statement`` in the block of ``parent`` holding it, or None when
    no block of ``parent`` holds it."""
    for field in _BLOCKS:
        block = getattr(parent, field, None)
        if isinstance(block, list):
            for position, held in enumerate(block):
                if held is statement:
                    return block[:position]
    return None


def preceding_statements(statement: ast.stmt, index: Index) -> Iterator[ast.stmt]:
    """The statements that ran just before ``statement`` whenever it runs, nearest first: those
    before it in its block, then (out of an ``if`` or ``with`` block) those before that
    statement; none from beyond a loop, ``try``, ``match`` or function."""
    node: ast.AST = statement
    parent = index.parents.get(id(node))
    while parent is not None:
        before = _before_in_block(node, parent)  # type: ignore[arg-type]
        if before is None:
            return
        yield from reversed(before)
        if not isinstance(parent, _THROUGH):
            return
        node, parent = parent, index.parents.get(id(parent))


def reaching_store(read: ast.Name, stores: list[ast.Name], index: Index) -> ast.Name | None:
    """The store among ``stores`` (every binding of the name in the read's function) whose
    value ``read`` certainly sees, or None when that is not certain."""
    statement = enclosing(read, index.parents, (ast.stmt,))
    if not isinstance(statement, ast.stmt) or isinstance(statement, ast.While):
        return None  # (a while test also sees what its body stores)
    for before in preceding_statements(statement, index):
        inside = [s for s in stores if _inside(s, before)]
        if inside:
            return _plain_target(before, inside)
    return None


def _plain_target(statement: ast.stmt, inside: list[ast.Name]) -> ast.Name | None:
    """The name ``statement`` stores when it is a plain assignment of it, else None."""
    targets = statement.targets if isinstance(statement, ast.Assign) else \
        [statement.target] if isinstance(statement, ast.AnnAssign) and statement.value else []
    direct = [t for t in targets if any(t is s for s in inside)]
    return direct[0] if direct and len(inside) == len(direct) else None
