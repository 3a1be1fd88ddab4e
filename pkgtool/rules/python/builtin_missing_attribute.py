"""PYC078: an attribute a builtin value lacks (``items.push(x)`` on a list, ``text.lenght``)."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity, shortened
from pkgtool.knowledge.rosdistro import typo_of
from pkgtool.knowledge.stdlib_names import stdlib_names
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._attribute_guards import guarded, probed_names
from pkgtool.rules.python._value_types import certain_type
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import index_of, python_files

_HABITS = {
    ("list", "push"): "append", ("list", "add"): "append", ("set", "append"): "add",
    ("set", "push"): "add", ("dict", "iteritems"): "items", ("dict", "itervalues"): "values",
    ("dict", "iterkeys"): "keys", ("str", "toUpperCase"): "upper",
    ("str", "toLowerCase"): "lower", ("str", "trim"): "strip",
}
"""Methods of other languages (or of Python 2) and what the builtin type calls them."""
_SPELLED = {("dict", "has_key"): "`key in {0}`", ("list", "length"): "`len({0})`",
            ("str", "length"): "`len({0})`", ("tuple", "length"): "`len({0})`",
            ("dict", "length"): "`len({0})`", ("list", "size"): "`len({0})`",
            ("str", "contains"): "`part in {0}`", ("list", "contains"): "`item in {0}`"}
"""Habits Python writes as an operator or a builtin function, not a method."""


@rule("PYC078", "builtin-missing-attribute", Severity.ERROR,
      fix="Use the method the builtin type has (see the message)")
def builtin_missing_attribute(package: Package) -> Iterator[Hit]:
    """Code reads an attribute that a list, dict, set, tuple, str, bytes or number lacks.

    ## What it does
    In every Python file of the package, reports `value.name` when `value` certainly holds a
    builtin list, dict, set, frozenset, tuple, str, bytes, int, float or bool and no Python
    from 3.10 to 3.13 gives that type the attribute: a literal (`'abc'.uper()`), or a local
    name or a node's `self.x` every binding of which gives that one type (`items = []`, then
    `items.push(1)`; `count = 0`, then `count.incr()`). Habits of other languages get the
    Python spelling (`push` is `append`, `has_key(k)` is `k in d`, `length` is `len()`); a
    typo gets the name it is a typo of. Private names, names the module probes with
    `hasattr`/`getattr`, and reads inside a `try` that catches AttributeError are left alone.

    ## Why is this bad?
    The line raises `AttributeError` when it runs, often inside a callback, where the error
    ends up in a log line and the node silently stops doing its job.

    ## Example
    ```python
    self.readings = []
    self.readings.push(msg.range)
    ```

    ## Use instead
    ```python
    self.readings = []
    self.readings.append(msg.range)
    ```
    """
    names = stdlib_names()
    for path, _, tree in python_files(package):
        index = index_of(tree)
        probed: frozenset[str] | None = None
        for node in index.attributes:
            if node.attr.startswith("_"):
                continue
            kind = certain_type(node.value, package, tree, index)
            known = names.get(f"builtins.{kind}")
            if known is None or node.attr in known[0]:
                continue
            probed = probed_names(index) if probed is None else probed
            if guarded(node, index, probed) or index.in_unevaluated_annotation(node):
                continue
            yield _hit(path, node, kind or "", known[0])


def _hit(path: str, node: ast.Attribute, kind: str, known: frozenset[str]) -> Hit:
    """The finding for ``node``, a read of an attribute the builtin type ``kind`` lacks."""
    shown = shortened(ast.unparse(node.value))
    owner = f"({shown})" if not isinstance(node.value, (ast.Name, ast.Attribute, ast.Call,
                                                        ast.Subscript, ast.Constant)) else shown
    meant = _HABITS.get((kind, node.attr)) or \
        typo_of(node.attr, frozenset(name for name in known if not name.startswith("_")))
    spelled = _SPELLED.get((kind, node.attr))
    fix = f"Write `{meant}`" if meant else f"Use {spelled.format(owner)}" if spelled else None
    hint = f" (did you mean `{meant}`?)" if meant else ""
    where = Span(path, node.end_lineno or node.lineno,
                 (node.end_col_offset or 0) - len(node.attr) + 1)
    return Hit(where, f"`{shown}` is a `{kind}`, which has no `{node.attr}`{hint}: the line "
               "raises AttributeError", fix)
