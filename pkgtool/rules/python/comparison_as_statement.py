"""PYC050: a comparison written as a statement (``msg.data == 'hi'``), which does nothing."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import TRIES, last_name, nodes_of_class
from pkgtool.model.package import Package, is_test_material
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import FUNCTIONS, Index, index_of, python_files

_TARGETS = (ast.Name, ast.Attribute, ast.Subscript)
"""What an assignment can store to: the left side of a comparison that may be meant as one."""


_SYMBOLS = {ast.Eq: "==", ast.NotEq: "!=", ast.Lt: "<", ast.LtE: "<=", ast.Gt: ">",
            ast.GtE: ">="}
"""The comparisons reported, by operator class, as written."""


def comparison_statements(tree: ast.Module) -> Iterator[ast.Compare]:
    """The ``a == b`` (``!=``, ``<``, ...) expressions that are whole statements."""
    for statement in nodes_of_class(tree, ast.Expr):
        value = statement.value  # type: ignore[attr-defined]
        if isinstance(value, ast.Compare) and len(value.ops) == 1 and \
                type(value.ops[0]) in _SYMBOLS:
            yield value


@rule("PYC050", "comparison-as-statement", Severity.ERROR,
      fix="Assign with `=`, or assert the comparison in a test: `assert x == y`")
def comparison_as_statement(package: Package) -> Iterator[Hit]:
    """A comparison `x == y` stands alone as a statement: it does nothing.

    ## What it does
    Reports a statement that is only a comparison (`msg.data == 'hello'`, `self.count == 0`,
    `add(1, 2) == 3` or `result != None` in a test; also `<`, `<=`, `>`, `>=`), in every
    Python file of the package.
    When the comparison holds a call (`cv2.waitKey(50) & 0xFF == ord('q')`), the call still
    runs: the message says so and proposes using the result, not removing the line. A test's
    comparison expected to raise (in `with pytest.raises(...)` or `assertRaises`, or alone in
    the body of a `try` with handlers) is left alone.

    ## Why is this bad?
    Python evaluates the comparison and drops the result: the assignment meant (`=`) never
    happens, so the message goes out empty or the counter is never reset, and a test
    missing its `assert` passes whatever the code does. Nothing fails to point at it.

    ## Example
    ```python
    msg = String()
    msg.data == 'hello'
    ```

    ## Use instead
    ```python
    msg = String()
    msg.data = 'hello'
    ```
    """
    for path, text, tree in python_files(package, ("==", "!=", "<", ">")):
        for compare in comparison_statements(tree):
            if is_test_material(path) and _expected_to_raise(compare, index_of(tree)):
                continue
            left, right = (_written(text, side) for side in (compare.left,
                                                             compare.comparators[0]))
            op = _SYMBOLS[type(compare.ops[0])]
            meant = f"`assert {left} {op} {right}`" if is_test_material(path) else \
                f"`{left} = {right}`" if isinstance(compare.left, _TARGETS) and op == "==" \
                else None
            called = meant is None and any(isinstance(node, ast.Call)
                                           for node in ast.walk(compare))
            effect = "its calls run, but the comparison is lost" if called else \
                "the statement does nothing"
            yield Hit(Span(path, compare.lineno, compare.col_offset + 1),
                      f"`{left} {op} {right}` compares and drops the result: {effect}" +
                      (f" (did you mean {meant}?)" if meant else ""),
                      f"Write {meant}" if meant else "Use the result (`if ...:`)" if called
                      else "Use the result, or remove the line")


_RAISES = frozenset({"raises", "assertRaises", "assertRaisesRegex"})
"""Context managers of tests that expect the block to raise."""


def _expected_to_raise(compare: ast.Compare, index: Index) -> bool:
    """True for a comparison a test runs to see it raise: in ``with pytest.raises(...)``
    (``assertRaises``), or alone in the body of a ``try`` that catches exceptions."""
    statement = index.parents.get(id(compare))
    parent = index.parents.get(id(statement))
    if isinstance(parent, TRIES) and parent.handlers and parent.body == [statement]:
        return True
    while parent is not None and not isinstance(parent, FUNCTIONS):
        if isinstance(parent, (ast.With, ast.AsyncWith)) and any(
                isinstance(item.context_expr, ast.Call) and
                last_name(item.context_expr.func) in _RAISES for item in parent.items):
            return True
        parent = index.parents.get(id(parent))
    return False


def _written(text: str, node: ast.expr) -> str:
    """``node`` as the source writes it (``0xFF``), or unparsed when that spans lines."""
    segment = ast.get_source_segment(text, node)
    return segment if segment and "\n" not in segment else ast.unparse(node)
