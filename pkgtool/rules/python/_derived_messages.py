"""Messages reached from a known message instance (PYC019): a local name bound once to one of
its fields (``header = msg.header``) or to an element of a field holding a sequence of
messages (``first = msg.poses[0]``), a ``for`` target or a comprehension's target over such a
field (``for pose in msg.poses``, ``[p.pose for p in msg.poses]``, with ``enumerate(...)``
too), and an element used where it is taken (``msg.poses[-1].pose``).

A name counts only when its scope (the function, the module, or the comprehension) binds it
exactly once, nothing inside that scope rebinds it, and the path to the field crosses no field
the code assigns (``msg.pose = ...``): every attribute taken on the name is then taken on that
message. Instances reached this way are followed again, a few levels deep (``for marker in
msg.markers: for point in marker.points``).
"""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.knowledge.message_fields import Message, element_message, nested_message
from pkgtool.rules.python._message_instances import (Instance, attributes_taken,
                                                     binding_counts, fields_taken, instance_of,
                                                     name_reads)
from pkgtool.rules.scopes import NESTED_SCOPES
from pkgtool.rules.syntax_trees import FUNCTIONS, Index

_LEVELS = 3
"""How many times instances reached are followed again."""


def derived_instances(instances: list[Instance[Message]], tree: ast.Module, index: Index
                      ) -> list[Instance[Message]]:
    """The message instances reached from ``instances`` (see the module's text)."""
    found: list[Instance[Message]] = []
    frontier = instances
    for _ in range(_LEVELS):
        frontier = [derived for instance in frontier
                    for derived in _reached(instance, tree, index)]
        if not frontier:
            break
        found.extend(frontier)
    return found


def _reached(instance: Instance[Message], tree: ast.Module, index: Index
             ) -> Iterator[Instance[Message]]:
    """The instances reached from the fields ``instance`` is used through (not through a
    field the code assigns)."""
    for node, message, path in fields_taken(instance, index):
        if path in instance.stored:
            continue
        element = element_message(message, node.attr)
        if element is not None:
            yield from _elements(node, element, tree, index)
        nested = nested_message(message, node.attr)
        if nested is not None:
            yield from _bound(node, nested, tree, index)


def _elements(field: ast.Attribute, element: Message, tree: ast.Module, index: Index
              ) -> Iterator[Instance[Message]]:
    """Instances of ``element``, the class of the messages the sequence ``field`` holds: a
    loop's or comprehension's target, an indexed element and a name bound to one."""
    parent = index.parents.get(id(field))
    if isinstance(parent, ast.Call) and isinstance(parent.func, ast.Name) and \
            parent.func.id == "enumerate" and len(parent.args) == 1 and \
            parent.args[0] is field and not parent.keywords:
        yield from _loop_target(parent, element, tree, index, enumerated=True)
    elif isinstance(parent, (ast.For, ast.AsyncFor, ast.comprehension)) and \
            parent.iter is field:
        yield from _loop_target(field, element, tree, index, enumerated=False)
    elif isinstance(parent, ast.Subscript) and parent.value is field and \
            isinstance(parent.ctx, ast.Load) and not isinstance(parent.slice, ast.Slice):
        above = index.parents.get(id(parent))
        if isinstance(above, ast.Attribute) and above.value is parent:
            yield instance_of(element, [above], [parent], index)
        yield from _bound(parent, element, tree, index)


def _loop_target(iterated: ast.expr, element: Message, tree: ast.Module, index: Index, *,
                 enumerated: bool) -> Iterator[Instance[Message]]:
    """The instance a ``for`` or comprehension over ``iterated`` binds its target to (the
    second name of ``i, x`` over ``enumerate(...)``)."""
    loop = index.parents.get(id(iterated))
    if not isinstance(loop, (ast.For, ast.AsyncFor, ast.comprehension)) or \
            loop.iter is not iterated:
        return
    target = loop.target
    if enumerated:
        target = target.elts[1] if isinstance(target, ast.Tuple) and \
            len(target.elts) == 2 else None  # type: ignore[assignment]
    if isinstance(target, ast.Name):
        scope = index.parents.get(id(loop)) if isinstance(loop, ast.comprehension) else \
            _scope(loop, tree, index)
        yield from _named(target.id, scope, element, index)


def _bound(value: ast.expr, message: Message, tree: ast.Module, index: Index
           ) -> Iterator[Instance[Message]]:
    """The instance of ``message`` a name is bound to by ``name = value``."""
    statement = index.parents.get(id(value))
    if isinstance(statement, ast.Assign) and statement.value is value and \
            len(statement.targets) == 1 and isinstance(statement.targets[0], ast.Name):
        yield from _named(statement.targets[0].id, _scope(statement, tree, index), message,
                          index)


def _named(name: str, scope: ast.AST | None, message: Message, index: Index
           ) -> Iterator[Instance[Message]]:
    """``name`` as an instance of ``message`` in ``scope``, when bound once there."""
    if scope is not None and binding_counts(scope)[name] == 1:
        uses, reads = attributes_taken(scope, name), name_reads(scope, name)
        if uses or reads:
            yield instance_of(message, uses, reads, index)


def _scope(statement: ast.AST, tree: ast.Module, index: Index) -> ast.AST | None:
    """The function whose body holds ``statement`` (also in a comprehension's or lambda's
    scope: None), ``tree`` at module level, None in a class body."""
    parent = index.parents.get(id(statement))
    while parent is not None and type(parent) not in NESTED_SCOPES:
        parent = index.parents.get(id(parent))
    if parent is None:
        return tree
    return parent if isinstance(parent, FUNCTIONS) else None
