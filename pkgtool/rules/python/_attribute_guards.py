"""Attribute reads that code expects may fail (PYC019, PYC023): names the module probes
with ``hasattr``/``getattr``, and reads inside a ``try`` that catches AttributeError; and
modules whose attributes may be made in ways not written as ``x.name = ...`` (PYC023,
PYC087)."""

from __future__ import annotations

import ast

from pkgtool.model.ast_nodes import descendants, nodes_of_class
from pkgtool.model.memo import per_tree
from pkgtool.rules.syntax_trees import Index

_BROAD = frozenset({"Exception", "BaseException"})
_PROBES = frozenset({"hasattr", "getattr"})
_DYNAMIC = frozenset({"setattr", "delattr", "vars", "__dict__", "__getattr__",
                      "__getattribute__", "__setattr__", "__slots__"})
"""Names whose use in a module means any attribute may exist."""
_BUILTINS = _DYNAMIC | {"exec"}
"""Those names, and builtins that do the same (``exec('self.x = 1')``), read as names (an
attribute ``app.exec`` is another thing)."""


_MODEL_LIBRARIES = frozenset({"transitions", "statemachine"})
"""Libraries that add attributes to the object given them as a model (``Machine(model=self,
states=...)`` makes ``self.state`` and a method per trigger)."""


def dynamic_attributes(tree: ast.Module) -> bool:
    """True when the module may create attributes in ways not written as ``x.name = ...``:
    also when it gives an object to a library as its model (``model=self``, or imports one
    of :data:`_MODEL_LIBRARIES`)."""
    return (any(isinstance(n, ast.Name) and n.id in _BUILTINS
                for n in nodes_of_class(tree, ast.Name))
            or any(isinstance(n, ast.keyword) and n.arg == "model"
                   for n in nodes_of_class(tree, ast.keyword))
            or any((n.module or "").split(".")[0] in _MODEL_LIBRARIES
                   if isinstance(n, ast.ImportFrom) else
                   any(a.name.split(".")[0] in _MODEL_LIBRARIES for a in n.names)
                   for n in nodes_of_class(tree, ast.Import, ast.ImportFrom))
            or any(isinstance(n, ast.Attribute) and n.attr in _DYNAMIC
                   for n in nodes_of_class(tree, ast.Attribute))
            or any(isinstance(n, ast.FunctionDef) and n.name in _DYNAMIC
                   for n in nodes_of_class(tree, ast.FunctionDef)))


def probed_names(index: Index) -> frozenset[str]:
    """Attribute names the module asks ``hasattr`` or ``getattr`` about: written out, or
    each of the names a loop or comprehension around the call gives ``hasattr`` or a
    ``getattr`` with a default (``all(hasattr(box, a) for a in ('xmin', 'xmax'))``; not
    ``getattr(v, axis) for axis in 'xyz'``, which reads what it expects to be there)."""
    names: set[str] = set()
    for call in index.calls:
        if isinstance(call.func, ast.Name) and call.func.id in _PROBES and len(call.args) > 1:
            asked = call.args[1]
            if isinstance(asked, ast.Constant) and isinstance(asked.value, str):
                names.add(asked.value)
            elif isinstance(asked, ast.Name) and (call.func.id == "hasattr" or
                                                  len(call.args) > 2):
                names.update(_looped_texts(call, asked.id, index))  # not getattr(v, axis)
    return frozenset(names)


def _looped_texts(node: ast.AST, name: str, index: Index) -> list[str]:
    """The strings a ``for`` loop or comprehension around ``node`` gives ``name`` from a
    literal tuple, list or set of them; none otherwise."""
    parent = index.parents.get(id(node))
    while parent is not None:
        loops = parent.generators if isinstance(
            parent, (ast.GeneratorExp, ast.ListComp, ast.SetComp, ast.DictComp)) else \
            [parent] if isinstance(parent, (ast.For, ast.AsyncFor)) else []
        for loop in loops:
            if isinstance(loop.target, ast.Name) and loop.target.id == name and \
                    isinstance(loop.iter, (ast.Tuple, ast.List, ast.Set)):
                return [e.value for e in loop.iter.elts
                        if isinstance(e, ast.Constant) and isinstance(e.value, str)]
        parent = index.parents.get(id(parent))
    return []


def guarded(node: ast.Attribute, index: Index, probed: frozenset[str]) -> bool:
    """True for a name the module probes for, or inside a ``try`` that catches
    AttributeError, or anything (``except Exception:``) without raising it again (a handler
    with a bare ``raise`` lets the error out): code that expects the attribute may be
    missing; or inside an ``except AttributeError:`` handler or the branch taken when a
    ``hasattr`` fails, the fallback of code written for two APIs (``info.k = ...`` tried,
    ``info.K = ...`` when that fails)."""
    if node.attr in probed:
        return True
    child, parent = node, index.parents.get(id(node))
    while parent is not None:
        if isinstance(parent, ast.Try) and child in parent.body and \
                any(_catches(handler) for handler in parent.handlers):
            return True
        if isinstance(parent, ast.ExceptHandler) and child is not parent.type and \
                "AttributeError" in _caught_names(parent):
            return True
        if isinstance(parent, ast.If) and _lacks_branch(parent, child):
            return True
        child, parent = parent, index.parents.get(id(parent))
    return False


def _lacks_branch(test: ast.If, child: ast.AST) -> bool:
    """True when ``child`` is in the branch of ``test`` taken when a ``hasattr`` fails: the
    ``else`` of ``if hasattr(x, 'a'):``, the body of ``if not hasattr(x, 'a'):`` (the other
    API's name in a shim for two versions)."""
    def probes(node: ast.expr) -> bool:
        return isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and \
            node.func.id == "hasattr"

    negated = isinstance(test.test, ast.UnaryOp) and isinstance(test.test.op, ast.Not)
    if negated and probes(test.test.operand):  # type: ignore[attr-defined]
        return any(child is s for s in test.body)
    return probes(test.test) and any(child is s for s in test.orelse)


@per_tree
def _catches(handler: ast.ExceptHandler) -> bool:
    """True when ``handler`` takes an AttributeError for good: it names AttributeError, or
    catches everything and has no bare ``raise``."""
    names = _caught_names(handler)
    if "AttributeError" in names:
        return True
    return bool(names & _BROAD) and not any(
        isinstance(n, ast.Raise) and n.exc is None
        for statement in handler.body for n in descendants(statement))


def _caught_names(handler: ast.ExceptHandler) -> set[str]:
    """The exception names ``handler`` catches (:data:`_BROAD` for a bare ``except:``)."""
    return {n.id for n in descendants(handler.type) if isinstance(n, ast.Name)} \
        if handler.type is not None else set(_BROAD)
