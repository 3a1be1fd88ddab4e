"""Names a module of a table does not define (PYC063 for the standard library, PYC076 for
NumPy): reads of ``module.name`` through an import and ``from module import name``."""

from __future__ import annotations

import ast
from collections.abc import Iterator, Mapping

from pkgtool.knowledge.rosdistro import typo_of
from pkgtool.model.ast_nodes import TRIES, descendants, nodes_of_class
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._attribute_guards import guarded, probed_names
from pkgtool.rules.python._message_instances import binding_counts
from pkgtool.rules.syntax_trees import Index, index_of, python_files, resolved_attributes

Table = Mapping[str, tuple[frozenset[str], bool]]
"""Module -> (the names it defines, whether the list is complete: False for a spelling
reference, where only a typo of a listed name counts as missing)."""
Missing = tuple[Span, str, str, str | None, str, tuple[Span, ...]]
"""Where, the module, the name, the name a typo away it has (or None), the exception, and the
places that use a name a ``from`` import binds (renamed with it)."""


def _missing(table: Table, module: str, name: str) -> tuple[bool, str | None]:
    """Whether ``module`` (one the table lists) certainly lacks ``name``, and the name a typo
    away it has. On a module whose list is a spelling reference only a typo counts."""
    names, complete = table[module]
    if name in names or name.startswith("_") or name == "*":  # `from math import *`
        return False, None
    meant = typo_of(name, names)
    return complete or meant is not None, meant


_TESTS = frozenset({"version_info", "hexversion", "platform", "name", "hasattr", "getattr",
                    "PY2", "PY3"})
"""Names in an ``if`` test that make its branches version- or platform-dependent."""


def _conditional(node: ast.AST, index: Index, *, any_try: bool) -> bool:
    """True under an ``if`` testing the Python version or the platform, or (``any_try``)
    inside any ``try``."""
    child, parent = node, index.parents.get(id(node))
    while parent is not None:
        if any_try and isinstance(parent, TRIES):
            return True
        if isinstance(parent, (ast.If, ast.IfExp)) and child is not parent.test and any(
                getattr(n, "id", getattr(n, "attr", None)) in _TESTS
                for n in descendants(parent.test)):
            return True
        child, parent = parent, index.parents.get(id(parent))
    return False


def missing_names(package: Package, table: Table) -> Iterator[Missing]:
    """Names the package's Python files take from a module of ``table`` that it lacks; not
    private names, names the module assigns or probes with ``hasattr``/``getattr``, uses
    inside ``try`` or under a test of the Python version or platform."""
    for path, _, tree in python_files(package):
        index = index_of(tree)
        stored: set[str | None] | None = None
        probed: frozenset[str] | None = None
        for node, owner, attr in resolved_attributes(index):
            if owner not in table:
                continue
            missing, meant = _missing(table, owner, attr)
            if not missing:
                continue
            stored = {index.qualified(n) for n in nodes_of_class(tree, ast.Attribute)
                      if not isinstance(n.ctx, ast.Load)} if stored is None else stored
            probed = probed_names(index) if probed is None else probed
            if f"{owner}.{attr}" in stored or guarded(node, index, probed) or \
                    _conditional(node, index, any_try=False):
                continue
            yield (Span(path, node.end_lineno or node.lineno,
                        (node.end_col_offset or 0) - len(attr) + 1), owner, attr, meant,
                   "AttributeError", ())
        for imported in index.import_froms:
            if imported.level or imported.module not in table or \
                    _conditional(imported, index, any_try=True):
                continue
            for alias in imported.names:
                missing, meant = _missing(table, imported.module, alias.name)
                if missing:
                    uses = _uses(path, tree, alias.name) if alias.asname is None else ()
                    yield (Span(path, imported.lineno, imported.col_offset + 1),
                           imported.module, alias.name, meant, "ImportError", uses)


def _uses(path: str, tree: ast.Module, name: str) -> tuple[Span, ...]:
    """Where the module reads ``name``, when nothing but one import binds it."""
    if binding_counts(tree)[name] != 1:
        return ()
    return tuple(Span(path, n.lineno, n.col_offset + 1) for n in nodes_of_class(tree, ast.Name)
                 if isinstance(n, ast.Name) and n.id == name and isinstance(n.ctx, ast.Load))


def used_on(uses: tuple[Span, ...]) -> str:
    """`` (the name is used on lines 9, 12)`` for the uses of a misspelt imported name."""
    if not uses:
        return ""
    lines = ", ".join(str(line) for line in sorted({span.line for span in uses}))
    return f" (the name is used on line{'s' if ',' in lines else ''} {lines})"
