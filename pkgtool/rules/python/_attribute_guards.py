"""Attribute reads that code expects may fail (PYC019, PYC023): names the module probes
with ``hasattr``/``getattr``, and reads inside a ``try`` that catches AttributeError."""

from __future__ import annotations

import ast

from pkgtool.model.ast_nodes import descendants
from pkgtool.model.memo import per_tree
from pkgtool.rules.syntax_trees import Index

_BROAD = frozenset({"Exception", "BaseException"})
_PROBES = frozenset({"hasattr", "getattr"})


def probed_names(index: Index) -> frozenset[str]:
    """Attribute names the module asks ``hasattr`` or ``getattr`` about."""
    return frozenset(call.args[1].value for call in index.calls
                     if isinstance(call.func, ast.Name) and call.func.id in _PROBES
                     and len(call.args) > 1 and isinstance(call.args[1], ast.Constant)
                     and isinstance(call.args[1].value, str))


def guarded(node: ast.Attribute, index: Index, probed: frozenset[str]) -> bool:
    """True for a name the module probes for, or inside a ``try`` that catches
    AttributeError, or anything (``except Exception:``) without raising it again (a handler
    with a bare ``raise`` lets the error out): code that expects the attribute may be
    missing; or inside an ``except AttributeError:`` handler, the fallback of code written
    for two APIs (``info.k = ...`` tried, ``info.K = ...`` when that fails)."""
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
        child, parent = parent, index.parents.get(id(parent))
    return False


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
