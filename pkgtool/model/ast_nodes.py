"""Every node of a syntax tree, collected once per tree and shared by the model and the rules.

``ast.walk`` costs a generator per node; the model and several rules each used to walk the
same tree again. :func:`nodes_of` walks it once (breadth first, the order of ``ast.walk``)
and keeps the list for the trees in use (``parse_tree`` returns one tree per file and text);
:func:`nodes_of_class` gives the nodes of a few classes without looking at the others.

These walks leave out the context and operator nodes (``ast.Load``, ``ast.Add``, ``ast.Eq``
...): a third of a tree's nodes, shared singletons without fields that tell nothing but the
class of their parent's ``ctx``, ``op`` or ``ops`` (read them there). They look only at
:data:`CHILD_FIELDS`.
"""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.model.memo import per_tree
from pkgtool.records import record

_LEAF_FIELDS = frozenset({"ctx", "op", "ops",  # the singletons the walks leave out
                          "id", "attr", "arg", "asname", "module", "level", "kind", "conversion",
                          "is_async", "simple", "rest", "tag", "kwd_attrs", "type_comment"})
"""Fields that never hold a node the walks take, in any node class (names, numbers, flags)."""


class _ChildFields(dict[type, tuple[str, ...]]):
    """The fields of each node class that may hold child nodes, in field order."""

    def __missing__(self, kind: type) -> tuple[str, ...]:
        found = tuple(name for name in kind._fields if name not in _LEAF_FIELDS
                      and not (kind is ast.Constant and name == "value"))
        self[kind] = found
        return found


CHILD_FIELDS = _ChildFields()
"""The fields of a node class the walks look at: ``CHILD_FIELDS[type(node)]``."""
_NODE = ast.AST
TRIES: tuple[type, ...] = tuple(getattr(ast, name) for name in ("Try", "TryStar")
                                if hasattr(ast, name))
"""The classes of ``try`` statements of the running Python (``try/except*`` from 3.11)."""


@record
class Walk:
    """Every node of a tree breadth first (the order of ``ast.walk``), each node's parent by
    ``id(node)``, and the nodes of each class (in walk order)."""

    nodes: tuple[ast.AST, ...]
    parents: dict[int, ast.AST]
    by_class: dict[type, list[ast.AST]]


@per_tree
def walk_once(tree: ast.AST) -> Walk:
    """The :class:`Walk` of ``tree``, computed once per tree object; treat both as read-only.

    Children are taken in field order (``ast.iter_child_nodes``), inline: this walk is the
    one every rule shares, and a call per node doubled its cost.
    """
    found: list[ast.AST] = [tree]
    parents: dict[int, ast.AST] = {}
    by_class: dict[type, list[ast.AST]] = {}
    append = found.append
    for node in found:  # the list grows while it is read: breadth first
        kind = type(node)
        if kind in by_class:
            by_class[kind].append(node)
        else:
            by_class[kind] = [node]
        for name in CHILD_FIELDS[kind]:
            value = getattr(node, name, None)
            if type(value) is list:
                for item in value:
                    if isinstance(item, _NODE):
                        parents[id(item)] = node
                        append(item)
            elif isinstance(value, _NODE):
                parents[id(value)] = node
                append(value)
    return Walk(tuple(found), parents, by_class)


def block_statements(body: list[ast.stmt], kinds: tuple[type, ...]) -> Iterator[ast.stmt]:
    """The statements of ``body``, each followed by those of the blocks (``body``, ``orelse``,
    ``finalbody``, then the ``except`` handlers) of the ones of ``kinds`` among them, at any
    depth: what runs at the level of ``body`` (a module's ``if``/``try`` blocks)."""
    for node in body:
        yield node
        if isinstance(node, kinds):
            for block in ("body", "orelse", "finalbody"):
                yield from block_statements(getattr(node, block, []), kinds)
            for handler in getattr(node, "handlers", []):
                yield from block_statements(handler.body, kinds)


def enclosing(node: ast.AST, parents: dict[int, ast.AST], kinds: tuple[type, ...]
              ) -> ast.AST | None:
    """The nearest node around ``node`` (by ``parents``: a :class:`Walk`'s) of one of
    ``kinds``, or None."""
    parent = parents.get(id(node))
    while parent is not None and not isinstance(parent, kinds):
        parent = parents.get(id(parent))
    return parent


def statement_of(node: ast.AST, parents: dict[int, ast.AST]) -> ast.AST:
    """The innermost statement holding ``node`` (``node`` itself for a statement), by
    ``parents`` (a :class:`Walk`'s)."""
    while not isinstance(node, ast.stmt):
        node = parents[id(node)]
    return node


def names_bound_by(node: ast.AST) -> list[str]:
    """The names ``node`` itself binds in the scope it stands in (a stored name, a parameter,
    a definition, an import, ``except ... as``, a ``match`` capture); not ``global`` or
    ``nonlocal`` declarations."""
    if isinstance(node, ast.Name):
        return [] if isinstance(node.ctx, ast.Load) else [node.id]
    if isinstance(node, ast.arg):
        return [node.arg]
    if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
        return [node.name]
    if isinstance(node, (ast.Import, ast.ImportFrom)):
        return [alias.asname or alias.name.split(".")[0] for alias in node.names]
    if isinstance(node, (ast.ExceptHandler, ast.MatchAs, ast.MatchStar)) and node.name:
        return [node.name]
    if isinstance(node, ast.MatchMapping) and node.rest:
        return [node.rest]
    return []


def child_nodes(node: ast.AST) -> list[ast.AST]:
    """``list(ast.iter_child_nodes(node))`` without its two generators, and without context
    and operator nodes."""
    found: list[ast.AST] = []
    for name in CHILD_FIELDS[type(node)]:
        value = getattr(node, name, None)
        if type(value) is list:
            for item in value:
                if isinstance(item, _NODE):
                    found.append(item)
        elif isinstance(value, _NODE):
            found.append(value)
    return found


def descendants(node: ast.AST) -> list[ast.AST]:
    """``list(ast.walk(node))`` (breadth first) without its generators, and without context
    and operator nodes: for the small parts of trees (a test, an expression) looked at once."""
    found = [node]
    for current in found:  # the list grows while it is read: breadth first
        found.extend(child_nodes(current))
    return found


@per_tree
def subtree(node: ast.AST) -> tuple[ast.AST, ...]:
    """:func:`descendants` of ``node`` computed once per node object (functions and classes
    several rules look at)."""
    return tuple(descendants(node))


def nodes_of(tree: ast.AST) -> tuple[ast.AST, ...]:
    """``tuple(ast.walk(tree))`` without context and operator nodes, computed once per tree
    object."""
    return walk_once(tree).nodes


def nodes_of_class(tree: ast.AST, *classes: type[ast.AST]) -> list[ast.AST]:
    """The nodes of ``tree`` that are instances of exactly these node classes (concrete ones:
    ``ast.Call``, not ``ast.expr``), grouped by class, each group in walk order."""
    by_class = walk_once(tree).by_class
    return [node for kind in classes for node in by_class.get(kind, ())]


EXITS = frozenset({"exit", "quit", "_exit"})
"""``sys.exit``, ``exit()``, ``quit()``, ``os._exit``: calls that end the program."""


def handler_stops(handler: ast.ExceptHandler) -> bool:
    """True for a handler that ends with ``raise`` or exits the program: what it catches stops
    the program (``except ImportError: sys.exit('pip install x')``)."""
    last = handler.body[-1] if handler.body else None
    if isinstance(last, ast.Raise):
        return True
    call = last.value if isinstance(last, ast.Expr) else None
    return isinstance(call, ast.Call) and last_name(call.func) in EXITS


def is_super_init(node: ast.AST) -> bool:
    """True for a call ``super().__init__(...)`` (``super(C, self).__init__(...)`` too)."""
    return isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and \
        node.func.attr == "__init__" and isinstance(node.func.value, ast.Call) and \
        isinstance(node.func.value.func, ast.Name) and node.func.value.func.id == "super"


def is_main_test(test: ast.expr) -> bool:
    """True for ``__name__ == '__main__'`` (either way round)."""
    if not (isinstance(test, ast.Compare) and len(test.ops) == 1 and
            isinstance(test.ops[0], ast.Eq)):
        return False
    return {ast.unparse(test.left), ast.unparse(test.comparators[0])} == \
        {"__name__", "'__main__'"}  # unparse writes every string in single quotes


def last_name(func: ast.expr) -> str:
    """The name a call's function ends in: ``f`` of ``f()``, ``exists`` of
    ``os.path.exists()``; ``""`` for another expression (``make()()``)."""
    return func.id if isinstance(func, ast.Name) else \
        func.attr if isinstance(func, ast.Attribute) else ""


_WRITING = frozenset("wax")
"""The letters of ``open()`` modes that make the file (write, append, exclusive create)."""


def opens_to_write(call: ast.Call) -> bool:
    """True when the mode ``call`` gives ``open()`` (second positional argument or
    ``mode=``) is a literal that makes the file (``'w'``, ``'ab'``, ``'x'``)."""
    mode = next((k.value for k in call.keywords if k.arg == "mode"),
                call.args[1] if len(call.args) > 1 else None)
    return isinstance(mode, ast.Constant) and isinstance(mode.value, str) and \
        bool(_WRITING & set(mode.value))
