"""PYC063: a name a standard library module does not define (``signal.SIGNT``, ``math.sqr``)."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rosdistro import typo_of
from pkgtool.knowledge.stdlib_names import stdlib_names
from pkgtool.model.ast_nodes import TRIES, descendants, nodes_of_class
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._attribute_guards import guarded, probed_names
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, index_of, python_files, resolved_attributes


def _missing(module: str, name: str) -> tuple[bool, str | None]:
    """Whether ``module`` (one the table lists) certainly lacks ``name``, and the name a typo
    away it has. On a platform-dependent module only a typo of a name it has counts."""
    names, portable = stdlib_names()[module]
    if name in names or name.startswith("_") or name == "*":  # `from math import *`
        return False, None
    meant = typo_of(name, names)
    return portable or meant is not None, meant


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


@rule("PYC063", "stdlib-missing-attribute", Severity.ERROR,
      fix="Use the name the module defines (see the message)")
def stdlib_missing_attribute(package: Package) -> Iterator[Hit]:
    """Code uses a name that a standard library module does not define.

    ## What it does
    In every Python file of the package, reports `module.name` read through an import, and
    `from module import name`, when a common standard library module (`math`, `json`,
    `random`, `threading`, `collections`, `datetime`, `pathlib`, `typing` and some forty
    more) defines no such name on any Python from 3.10 to 3.13 (Humble to Rolling): `math.sqr`,
    `random.randInt`, `collections.Mapping` (gone since 3.10). For modules whose names depend
    on the platform (`os`, `os.path`, `sys`, `signal`, `time`, `socket`, `subprocess`,
    `select`, `errno`, `platform`), only a name a typo away from one Linux's Python has is
    reported: `signal.SIGNT`, `os.pah.join`. Private names, names the module assigns or probes
    with `hasattr`/`getattr`, and uses inside `try` (and imports inside `try` or `if`) are left
    alone.

    ## Why is this bad?
    The line raises `AttributeError` (an import, `ImportError`) when it runs: often in a
    callback, long after the node started, or at start-up for a console script, in setup.py
    for the build, or in a launch file for the launch.

    ## Example
    ```python
    signal.signal(signal.SIGNT, handler)
    distance = math.sqr(dx * dx + dy * dy)
    ```

    ## Use instead
    ```python
    signal.signal(signal.SIGINT, handler)
    distance = math.sqrt(dx * dx + dy * dy)
    ```
    """
    table = stdlib_names()
    for path, _, tree in python_files(package):
        index = index_of(tree)
        stored: set[str | None] | None = None
        probed: frozenset[str] | None = None
        for node, owner, attr in resolved_attributes(index):
            if owner not in table:
                continue
            missing, meant = _missing(owner, attr)
            if not missing:
                continue
            stored = {index.qualified(n) for n in nodes_of_class(tree, ast.Attribute)
                      if not isinstance(n.ctx, ast.Load)} if stored is None else stored
            probed = probed_names(index) if probed is None else probed
            if f"{owner}.{attr}" in stored or guarded(node, index, probed) or \
                    _conditional(node, index, any_try=False):
                continue
            yield _hit(Span(path, node.end_lineno or node.lineno,
                            (node.end_col_offset or 0) - len(attr) + 1), owner, attr, meant,
                       "AttributeError")
        for imported in index.import_froms:
            if imported.level or imported.module not in table or \
                    _conditional(imported, index, any_try=True):
                continue
            for alias in imported.names:
                missing, meant = _missing(imported.module, alias.name)
                if missing:
                    yield _hit(Span(path, imported.lineno, imported.col_offset + 1),
                               imported.module, alias.name, meant, "ImportError")


def _hit(span: Span, module: str, name: str, meant: str | None, error: str) -> Hit:
    if module == "collections" and name in stdlib_names()["collections.abc"][0]:
        return Hit(span, f"`collections` has no `{name}` since Python 3.10, which moved it to "
                   f"`collections.abc`: the line raises {error}",
                   f"Use `collections.abc.{name}`")
    hint = f" (did you mean `{meant}`?)" if meant else ""
    return Hit(span, f"`{module}` has no `{name}` on Python 3.10-3.13{hint}: the line raises "
               f"{error}", f"Write `{meant}`" if meant else None)
