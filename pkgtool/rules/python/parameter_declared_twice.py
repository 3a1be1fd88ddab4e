"""PYC027: a node declares the same parameter twice in a row of straight-line code."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import child_nodes
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import node_subclasses
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import FUNCTIONS, Index, installed_trees

_SIMPLE = (ast.Expr, ast.Assign, ast.AnnAssign, ast.AugAssign)
"""Statements that run whole whenever the function body reaches them."""
_DECLARING = frozenset({"declare_parameter", "declare_parameters"})


def _around_declarations(index: Index) -> set[int]:
    """Ids of the ``x.declare_parameter(s)`` calls of the module and of every node around
    them: the statements worth a look (most hold none)."""
    found: set[int] = set()
    for call in index.calls:
        if isinstance(call.func, ast.Attribute) and call.func.attr in _DECLARING:
            node: ast.AST | None = call
            while node is not None and id(node) not in found:
                found.add(id(node))
                node = index.parents.get(id(node))
    return found


def _declared(statement: ast.stmt, receiver: str) -> Iterator[tuple[str, ast.Call]]:
    """The literal names ``receiver.declare_parameter(s)`` calls of a simple statement
    declare (not inside a lambda or comprehension, which may not run)."""
    if not isinstance(statement, _SIMPLE):
        return
    stack: list[ast.AST] = [statement]
    while stack:
        node = stack.pop()
        if isinstance(node, (ast.Lambda, ast.ListComp, ast.SetComp, ast.DictComp,
                             ast.GeneratorExp, ast.IfExp, ast.BoolOp)):
            continue
        stack.extend(child_nodes(node))
        if not (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and
                isinstance(node.func.value, ast.Name) and node.func.value.id == receiver):
            continue
        first = node.args[0] if node.args else None
        if node.func.attr == "declare_parameter" and isinstance(first, ast.Constant) and \
                isinstance(first.value, str):
            yield first.value, node
        elif node.func.attr == "declare_parameters" and isinstance(first, ast.Constant) and \
                len(node.args) > 1 and isinstance(node.args[1], (ast.List, ast.Tuple)):
            for item in node.args[1].elts:
                name = item.elts[0] if isinstance(item, ast.Tuple) and item.elts else None
                if isinstance(name, ast.Constant) and isinstance(name.value, str):
                    yield ".".join(filter(None, (str(first.value), name.value))), node


@rule("PYC027", "parameter-declared-twice", Severity.ERROR,
      fix="Declare each parameter once; read it again with `get_parameter`")
def parameter_declared_twice(package: Package) -> Iterator[Hit]:
    """A `Node` subclass declares the same parameter twice in one run of a method.

    ## What it does
    In the methods of classes deriving from rclpy's node classes, looks at the statements
    of the method body itself (not inside `if`, `try`, loops, `with`, lambdas or
    comprehensions: they run whenever the method does) and reports a
    `self.declare_parameter('name', ...)` (or a name of `self.declare_parameters(ns, [...])`)
    for a name the same body already declared with a literal name.

    ## Why is this bad?
    rclpy raises `ParameterAlreadyDeclaredException` on the second declaration: the node
    dies in its constructor. It usually comes from a copied line whose name was not changed.

    ## Example
    ```python
    self.declare_parameter('speed', 0.5)
    self.declare_parameter('speed', 1.0)  # meant 'turn_speed'
    ```

    ## Use instead
    ```python
    self.declare_parameter('speed', 0.5)
    self.declare_parameter('turn_speed', 1.0)
    ```
    """
    for module, _, index in installed_trees(package):
        declaring = _around_declarations(index)
        for cls in node_subclasses(index):
            for method in (s for s in cls.body if isinstance(s, FUNCTIONS)):
                positional = [*method.args.posonlyargs, *method.args.args]
                if method.decorator_list or not positional:
                    continue
                seen: dict[str, ast.Call] = {}
                for statement in method.body:
                    if id(statement) not in declaring:
                        continue
                    for name, call in _declared(statement, positional[0].arg):
                        if name in seen and seen[name] is not call:
                            yield Hit(Span(module.path, call.lineno, call.col_offset + 1),
                                      f"`{name}` is declared again (first on line "
                                      f"{seen[name].lineno}): rclpy raises "
                                      "ParameterAlreadyDeclaredException",
                                      related=(Span(module.path, seen[name].lineno,
                                                    seen[name].col_offset + 1),))
                        seen.setdefault(name, call)
