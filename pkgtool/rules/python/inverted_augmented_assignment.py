"""PYC047: ``x =+ 1`` (an assignment of a signed value) where ``x += 1`` was meant."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import python_files

_SIGNS = {ast.UAdd: "+", ast.USub: "-"}


def inverted_assignments(text: str, tree: ast.Module) -> Iterator[tuple[ast.Assign, str]]:
    """(assignment, sign) of ``target =+ value`` and ``target =- value``: the sign right after
    the ``=``, a space between it and the value, all on one line."""
    lines = text.splitlines()
    for node in nodes_of_class(tree, ast.Assign):
        assert isinstance(node, ast.Assign)
        value = node.value
        sign = _SIGNS.get(type(value.op)) if isinstance(value, ast.UnaryOp) else None
        if sign is None or len(node.targets) != 1 or value.lineno != value.end_lineno or \
                value.lineno > len(lines):
            continue
        line = lines[value.lineno - 1].encode("utf-8")  # ast columns count bytes
        if line[value.col_offset - 1:value.col_offset + 2] == f"={sign} ".encode():
            yield node, sign


@rule("PYC047", "inverted-augmented-assignment", Severity.WARNING,
      fix="Write the augmented assignment: `+=` (or `-=`)")
def inverted_augmented_assignment(package: Package) -> Iterator[Hit]:
    """An assignment `x =+ 1` or `x =- 1`, where `x += 1` or `x -= 1` was meant.

    ## What it does
    Reports an assignment whose value is a number or expression with a sign written right
    after the `=` and apart from what follows (`count =+ 1`, `self.speed =- 0.1`), in every
    Python file of the package. `x = -1` and `x = +offset` are left alone.

    ## Why is this bad?
    `=+` is not an operator: Python reads `count =+ 1` as `count = +1`, so the counter stays
    at 1 instead of counting, and `self.speed =- 0.1` sets the speed to -0.1 instead of
    slowing down. Nothing fails; the node just misbehaves.

    ## Example
    ```python
    def on_timer(self):
        self.count =+ 1
    ```

    ## Use instead
    ```python
    def on_timer(self):
        self.count += 1
    ```
    """
    for path, text, tree in python_files(package, ("=+ ", "=- ")):
        for node, sign in inverted_assignments(text, tree):
            target = ast.unparse(node.targets[0])
            operand = ast.unparse(node.value.operand)  # type: ignore[attr-defined]
            yield Hit(Span(path, node.lineno, node.col_offset + 1),
                      f"`{target} ={sign} {operand}` sets `{target}` to `{sign}{operand}`: "
                      f"`={sign}` is `=` and a sign, the augmented assignment is `{sign}=`",
                      f"Write `{target} {sign}= {operand}`")
