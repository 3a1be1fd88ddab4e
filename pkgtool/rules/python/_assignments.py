"""What a local name or a node's ``self.x`` is assigned, and the futures done callbacks get
(PYC046, and the service responses PYC019 checks).

A function's local name is known when every binding of it in the function (nested scopes
included) is a plain assignment ``name = value``. ``self.x`` is known when every store of it
is ``self.x = value`` (one target): the stores in the methods of the class when it derives
from rclpy's node classes alone, else every store of an attribute ``x`` in the package (None
when a module may store attributes unseen).
"""

from __future__ import annotations

import ast
from typing import Pattern

from pkgtool.model.ast_nodes import nodes_of_class, subtree
from pkgtool.model.package import Package
from pkgtool.rules.node_api import bases_are_nodes
from pkgtool.rules.python._message_instances import (binding_counts, callback_function, kept,
                                                     method_receiver)
from pkgtool.rules.python._value_types import attribute_stores, receiver_class
from pkgtool.rules.scopes import scope_bindings
from pkgtool.rules.syntax_trees import Index, installed_tree_of

Assigned = list[tuple[ast.expr, Index]]
"""The values assigned, each with the index of its module."""


def parameter_annotation(function: ast.FunctionDef | ast.AsyncFunctionDef, name: str
                         ) -> ast.expr | None:
    """The annotation of the parameter ``name`` of ``function`` (``future: Future``), when
    nothing in the function rebinds it."""
    arguments = function.args
    parameters = (*arguments.posonlyargs, *arguments.args, *arguments.kwonlyargs)
    note = next((a.annotation for a in parameters if a.arg == name), None)
    return note if note is not None and scope_bindings(function)[name] == 1 else None


def annotated_name(note: ast.expr | None) -> str | None:
    """The class name an annotation writes: ``Grid`` or the forward reference ``'Grid'``."""
    if isinstance(note, ast.Name):
        return note.id
    return note.value if isinstance(note, ast.Constant) and isinstance(note.value, str) \
        else None


def is_none(value: ast.expr) -> bool:
    """True for the constant None (a placeholder assigned before the object is made)."""
    return isinstance(value, ast.Constant) and value.value is None


def _local_values(tree: ast.Module, index: Index) -> dict[tuple[int, str], list[ast.expr]]:
    """``name = value`` assignments by (id of the function they are in, name)."""
    found: dict[tuple[int, str], list[ast.expr]] = {}
    for node in nodes_of_class(tree, ast.Assign):
        assert isinstance(node, ast.Assign)
        target = node.targets[0]
        function = index.enclosing_function(node, through_lambdas=False)
        if len(node.targets) == 1 and isinstance(target, ast.Name) and function is not None:
            found.setdefault((id(function), target.id), []).append(node.value)
    return found


def _local(name: ast.Name, tree: ast.Module, index: Index) -> Assigned | None:
    function = index.enclosing_function(name, through_lambdas=False)
    if function is None:
        return None
    assignments = kept(tree, "local assignments", lambda: _local_values(tree, index))
    values = assignments.get((id(function), name.id), [])
    if len(values) != binding_counts(function)[name.id]:
        return None
    return [(value, index) for value in values]


def _class_stores(cls: ast.ClassDef, name: str, index: Index) -> list[ast.Attribute]:
    """The stores of ``<receiver>.name`` in the plain methods of ``cls``."""
    return kept(cls, "stores by attribute", lambda: _stores_by_attribute(cls, index)).get(name, [])


def _stores_by_attribute(cls: ast.ClassDef, index: Index) -> dict[str, list[ast.Attribute]]:
    """The stores of ``<receiver>.x`` in the plain methods of ``cls``, by ``x``."""
    found: dict[str, list[ast.Attribute]] = {}
    for node in subtree(cls):
        if isinstance(node, ast.Attribute) and not isinstance(node.ctx, ast.Load) and \
                receiver_store(node, index) is cls:
            found.setdefault(node.attr, []).append(node)
    return found


def receiver_store(node: ast.Attribute, index: Index) -> ast.ClassDef | None:
    """The class whose plain method ``node`` (``self.x``) is taken on the receiver of, or
    None (a store on anything else: ``node.x``, ``self.x`` in a nested function)."""
    if not isinstance(node.value, ast.Name):
        return None
    method = index.enclosing_function(node, through_lambdas=False)
    cls = index.parents.get(id(method))
    return cls if isinstance(cls, ast.ClassDef) and \
        method_receiver(method) == node.value.id else None


def _attribute(value: ast.Attribute, package: Package, index: Index) -> Assigned | None:
    cls = receiver_class(value.value, index)
    everywhere = attribute_stores(package) if cls is not None else None
    if not everywhere or value.attr not in everywhere:
        return None  # not a method's receiver, attributes stored unseen, or never stored
    assert cls is not None
    own = bool(cls.bases) and bases_are_nodes(cls, index)
    stores = [(n, index) for n in _class_stores(cls, value.attr, index)] if own else \
        everywhere[value.attr]
    found: Assigned = []
    for store, store_index in stores:
        parent = store_index.parents.get(id(store))
        if not (isinstance(parent, ast.Assign) and parent.targets == [store]):
            return None
        found.append((parent.value, store_index))
    return found


def assigned_values(value: ast.expr, package: Package, tree: ast.Module, index: Index
                    ) -> Assigned | None:
    """Every value assigned to the local name or ``self.x`` ``value`` reads (see the module's
    doc), or None when some binding is no plain assignment."""
    if isinstance(value, ast.Name):
        return _local(value, tree, index)
    if isinstance(value, ast.Attribute) and isinstance(value.ctx, ast.Load):
        return _attribute(value, package, index)
    return None


_DEPTH = 8
"""How many names deep :func:`made_class` follows a value (``b = Path()``, ``a = b``)."""


def made_class(value: ast.expr, package: Package, tree: ast.Module, index: Index,
               kind: Pattern[str], depth: int = 0) -> str | None:
    """The class of qualified name matching ``kind`` (``pkg.msg.Name``) that ``value`` (in
    ``tree``) is certainly an instance of: a call of it, or a local name or ``self.x`` every
    assignment of which is one (None aside), followed through at most :data:`_DEPTH` names
    (``a = b`` and ``b = a`` loop)."""
    if isinstance(value, ast.Call):
        made = index.qualified(value.func) if isinstance(value.func, (ast.Name, ast.Attribute)) \
            else None
        return made if made and kind.fullmatch(made) else None
    assigned = assigned_values(value, package, tree, index) if depth < _DEPTH else None
    trees = installed_tree_of(package) if assigned else {}
    return sole({made_class(v, package, trees[id(i)], i, kind, depth + 1)
                 for v, i in assigned or () if not is_none(v)})


def sole(classes: set[str | None]) -> str | None:
    """The one class of ``classes``, or None (none, several, or one unknown)."""
    return next(iter(classes)) if len(classes) == 1 else None


def _done_callback_futures(tree: ast.Module, index: Index) -> dict[int, list[ast.expr]]:
    found: dict[int, list[ast.expr]] = {}
    for call in index.calls:
        func = call.func
        if not (isinstance(func, ast.Attribute) and func.attr == "add_done_callback" and
                len(call.args) == 1 and not call.keywords):
            continue
        named = callback_function(call.args[0], tree, index)
        if named is None:
            continue
        function, skip = named
        parameters = [*function.args.posonlyargs, *function.args.args]
        if len(parameters) <= skip or binding_counts(function)[parameters[skip].arg] != 1:
            continue
        parameter = parameters[skip].arg
        for node in subtree(function):
            if isinstance(node, ast.Name) and node.id == parameter:
                found.setdefault(id(node), []).append(func.value)
    return found


def done_callback_futures(tree: ast.Module, index: Index) -> dict[int, list[ast.expr]]:
    """By id of each name that is the future a done callback gets (the first parameter, after
    any receiver, of a function passed to ``add_done_callback``, never rebound), the futures
    it is registered on (``self.pending`` in ``self.pending.add_done_callback(...)``)."""
    return kept(tree, "done callback futures", lambda: _done_callback_futures(tree, index))
