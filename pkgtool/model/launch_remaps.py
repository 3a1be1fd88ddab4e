"""The ``remappings=`` of a Python launch node that launch_ros certainly rejects.

launch_ros's ``Node`` (and ``ComposableNode``) iterates ``remappings`` and requires each
item to be a tuple of length two (``normalize_remap_rule``: ``TypeError`` otherwise), so a
single pair not in a list (``('a', 'b')``: its items are strings), a string, a non-empty
dict (its keys are iterated) and a list holding a string, a list or a tuple of another
length all fail when the launch description is built. Only displays and literals (also
through a name assigned one) are judged; anything else may hold pairs.
"""

from __future__ import annotations

import ast
from collections.abc import Callable

_NO_TUPLES = (ast.Constant, ast.JoinedStr, ast.List, ast.ListComp, ast.Dict, ast.DictComp,
              ast.Set, ast.SetComp)
"""Expressions that never give a tuple."""


def _not_a_pair(item: ast.expr) -> bool:
    """True for an item that is certainly no tuple of two: a literal, a list, dict or set
    display, an f-string, a tuple display of another length."""
    if isinstance(item, ast.Tuple):
        return len(item.elts) != 2 and not any(isinstance(e, ast.Starred) for e in item.elts)
    return isinstance(item, _NO_TUPLES)


def not_pairs(node: ast.expr | None, resolve: Callable[[ast.expr | None], ast.expr | None]
              ) -> ast.expr | None:
    """The part of a ``remappings=`` value that makes launch_ros reject it: the whole value
    (a string, a dict, a single pair) or the first item that is no pair, or the name given
    when the value it is assigned is wrong; None when the value is not certainly wrong (a name
    or call not read, ``None``, pairs). ``resolve`` follows a name to its assigned value."""
    found = _wrong_part(resolve(node))
    return node if found is not None and isinstance(node, ast.Name) else found


def _wrong_part(node: ast.expr | None) -> ast.expr | None:
    """:func:`not_pairs` of a value that is no name."""
    if isinstance(node, ast.Constant):
        return node if node.value is not None and node.value != "" else None
    if isinstance(node, ast.JoinedStr):
        return node if node.values else None
    if isinstance(node, ast.Dict):
        return node if any(k is not None and not isinstance(k, ast.Tuple) for k in node.keys) \
            else None
    if isinstance(node, (ast.List, ast.Tuple, ast.Set)):
        return next((item for item in node.elts if _not_a_pair(item)), None)
    return None
