"""Every node of a syntax tree, collected once per tree and shared by the model and the rules.

``ast.walk`` costs a generator per node; the model and several rules each used to walk the
same tree again. :func:`nodes_of` walks it once (breadth first, the order of ``ast.walk``)
and keeps the list for the trees in use (``parse_tree`` returns one tree per file and text).
"""

from __future__ import annotations

import ast
from dataclasses import dataclass

from pkgtool.model.memo import per_object

_TREES = 64
"""How many trees' node lists stay: more than any package has modules being checked at once."""


@dataclass(frozen=True, slots=True)
class Walk:
    """Every node of a tree breadth first (the order of ``ast.walk``), and each node's parent
    by ``id(node)``."""

    nodes: tuple[ast.AST, ...]
    parents: dict[int, ast.AST]


@per_object(_TREES)
def walk_once(tree: ast.AST) -> Walk:
    """The :class:`Walk` of ``tree``, computed once per tree object; treat both as read-only.

    Children are taken in field order (``ast.iter_child_nodes``), inline: this walk is the
    one every rule shares, and a call per node doubled its cost.
    """
    found: list[ast.AST] = [tree]
    parents: dict[int, ast.AST] = {}
    append = found.append
    for node in found:  # the list grows while it is read: breadth first
        for name in node._fields:
            value = getattr(node, name, None)
            if type(value) is list:
                for item in value:
                    if isinstance(item, ast.AST):
                        parents[id(item)] = node
                        append(item)
            elif isinstance(value, ast.AST):
                parents[id(value)] = node
                append(value)
    return Walk(tuple(found), parents)


def nodes_of(tree: ast.AST) -> tuple[ast.AST, ...]:
    """``tuple(ast.walk(tree))``, computed once per tree object."""
    return walk_once(tree).nodes
