"""PYC042: a str and a number joined with ``+``."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._field_reads import field_reads, value_type
from pkgtool.rules.python._value_types import NUMBER_TYPES
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import installed_trees


def _error(left: str, right: str) -> str:
    """Python's TypeError for ``left + right``, one a str and the other a number."""
    if left == "str":
        return f'can only concatenate str (not "{right}") to str'
    return f"unsupported operand type(s) for +: '{left}' and 'str'"


@rule("PYC042", "text-plus-number", Severity.ERROR,
      fix="Format the number into the text: `f'count: {self.count}'`")
def text_plus_number(package: Package) -> Iterator[Hit]:
    """A str and a number are added with `+`.

    ## What it does
    Reports `a + b` (and `a += b`) where one side is certainly a str and the other certainly
    an int, float or bool: literals, builtin conversions (`str(x)`, `len(x)`), local names every
    assignment of which gives that type, a node's `self.x` every store of which in the
    package does, fields of known messages (`msg.linear.x` is a float, `msg.data` of a
    `String` a str), and parameter values of a known type (`self.get_parameter('period')
    .value` when the node declares `period` with `0.5`, or `.get_parameter_value()
    .double_value`).

    ## Why is this bad?
    Python does not convert numbers to text on `+`: `'Count: ' + self.count` raises
    `TypeError: can only concatenate str (not "int") to str`. In a timer or subscription
    callback the exception ends the node on the first message it logs or publishes.

    ## Example
    ```python
    self.count += 1
    msg.data = 'Hello World: ' + self.count
    ```

    ## Use instead
    ```python
    self.count += 1
    msg.data = f'Hello World: {self.count}'
    ```
    """
    for module, tree, index in installed_trees(package):
        adds = [n for n in nodes_of_class(tree, ast.BinOp, ast.AugAssign)
                if isinstance(n.op, ast.Add)]  # type: ignore[attr-defined]
        fields = field_reads(tree, index, package) if adds else {}
        for node in adds:
            sides = (node.left, node.right) if isinstance(node, ast.BinOp) else \
                (node.target, node.value)  # type: ignore[attr-defined]
            left, right = (value_type(side, fields, package, tree, index) for side in sides)
            if left is not None and right is not None and "str" in (left, right) and \
                    {left, right} & NUMBER_TYPES:
                number = right if right in NUMBER_TYPES else left
                article = "an" if number == "int" else "a"
                yield Hit(Span(module.path, node.lineno, node.col_offset + 1),  # type: ignore
                          f"`{ast.unparse(node)}` adds {article} {number} to a str: Python "
                          f"raises TypeError: {_error(left, right)}")
