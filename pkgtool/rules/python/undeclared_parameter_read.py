"""PYC014: a Node subclass reads a parameter it never declares."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_parameters import BUILT_IN, near, node_classes, write_meant
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, installed_trees

_REPEATED_OR_GUARDED = (ast.For, ast.AsyncFor, ast.While, ast.Try, ast.Lambda,
                        ast.ListComp, ast.SetComp, ast.DictComp, ast.GeneratorExp)


@rule("PYC014", "undeclared-parameter-read", Severity.ERROR,
      fix="Declare the parameter first: `self.declare_parameter('name', default)`")
def undeclared_parameter_read(package: Package) -> Iterator[Hit]:
    """A `Node` subclass reads a parameter that its code never declares.

    ## What it does
    In classes derived directly from rclpy's `Node`, checks the literal names given to
    `self.get_parameter('name')` and `self.get_parameters([...])` against the names the
    module declares with `declare_parameter` and `declare_parameters` (with their namespace
    prefix: `ns.name`), called directly or through a name bound only to the method in its
    function (`p = self.declare_parameter`, then `p('rate', 1.0)`). Also reports a read that
    comes before every declaration of its name in the same method, where each runs once
    (none in a loop, a `try` or a nested function), and a `self.set_parameters([...])` of a
    `Parameter('name', ...)` (made in the list, or bound once to a name the list holds) whose
    name the class never declares. `get_parameter_or` and `has_parameter` are not checked.
    Skipped when the module uses `allow_undeclared_parameters` or
    `automatically_declare_parameters_from_overrides`, declares a name that is not a
    literal, uses the method otherwise (passed to `map`, say), or the class derives from
    another class besides `Node`, or hands `self` to other code.

    ## Why is this bad?
    `get_parameter` (and `set_parameters`) raises `ParameterNotDeclaredException` for a name
    never declared (or not declared yet): the node dies where it reads it, often a
    misspelling of a declared name.

    ## Example
    ```python
    self.declare_parameter('period', 0.5)
    period = self.get_parameter('perod').value
    ```

    ## Use instead
    ```python
    self.declare_parameter('period', 0.5)
    period = self.get_parameter('period').value
    ```
    """
    indexes = {module.path: index for module, _, index in installed_trees(package)}
    for cls in node_classes(package):
        if cls.skip:
            continue
        declared = [d.name for d in cls.declared]
        for name, span in cls.reads:
            if name not in declared and name not in BUILT_IN:
                yield Hit(span, f"`{cls.name}` reads parameter `{name}` but never declares "
                          f"it{near(name, declared)}: ParameterNotDeclaredException",
                          write_meant(name, declared))
            elif cls.path in indexes and (later := _declared_later(
                    indexes[cls.path], span, [d.span for d in cls.declared if d.name == name])):
                yield Hit(span, f"`{cls.name}` reads parameter `{name}` before it declares it "
                          f"(line {later.line}): ParameterNotDeclaredException", None,
                          (later,))
        for name, span in cls.sets:
            if name not in declared and name not in BUILT_IN:
                yield Hit(span, f"`{cls.name}` sets parameter `{name}` but never declares "
                          f"it{near(name, declared)}: `set_parameters` raises "
                          "ParameterNotDeclaredException", write_meant(name, declared))


def _declared_later(index: Index, read: Span, declarations: list[Span]) -> Span | None:
    """The first declaration when the read and every declaration are calls run once, in this
    order, by the same method (not in a loop, a ``try`` or a nested function); else None."""
    calls = {(c.lineno, c.col_offset + 1): c for c in index.calls}
    nodes = [calls.get((s.line, s.col)) for s in (read, *declarations)]
    if not declarations or any(n is None for n in nodes):
        return None
    methods = {id(index.enclosing_function(n)) for n in nodes}
    first = min(declarations, key=lambda s: (s.line, s.col))
    if len(methods) != 1 or (read.line, read.col) >= (first.line, first.col):
        return None
    for node in nodes:
        parent = index.parents.get(id(node))
        while parent is not None and not isinstance(parent, (ast.FunctionDef,
                                                             ast.AsyncFunctionDef)):
            if isinstance(parent, _REPEATED_OR_GUARDED):
                return None
            parent = index.parents.get(id(parent))
    return first
