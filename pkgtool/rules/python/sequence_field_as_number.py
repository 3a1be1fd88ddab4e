"""PYC043: a message's sequence field compared with, or computed with, a number."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._field_reads import ARRAY_SEQUENCE, field_reads, operated_with
from pkgtool.rules.python._message_instances import binding_counts
from pkgtool.rules.python._value_types import NUMBER_TYPES, certain_type
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, installed_trees


def _sequence_reads(tree: ast.Module, index: Index, package: Package
                    ) -> Iterator[tuple[ast.expr, str, str]]:
    """(expression, ``pkg/msg/Type.field``, its type) of every read of a message's sequence
    field (``msg.ranges``, ``msg.ranges[10:20]``), and of local names bound only to one."""
    for read in field_reads(tree, index, package).values():
        if read.kind.startswith("sequence<"):
            yield from _spread(read.node, read.field, read.kind, index)


def _spread(read: ast.expr, field: str, kind: str, index: Index
            ) -> Iterator[tuple[ast.expr, str, str]]:
    """``read``, a slice of it, and the reads of a local name bound once to either."""
    parent = index.parents.get(id(read))
    if isinstance(parent, ast.Subscript) and parent.value is read and \
            isinstance(parent.slice, ast.Slice):
        read, parent = parent, index.parents.get(id(parent))
    yield read, field, kind
    if isinstance(parent, ast.Assign) and len(parent.targets) == 1 and \
            isinstance(parent.targets[0], ast.Name):
        name = parent.targets[0].id
        function = index.enclosing_function(parent, through_lambdas=False)
        if function is not None and binding_counts(function)[name] == 1:
            yield from ((n, field, kind) for n in ast.walk(function)
                        if isinstance(n, ast.Name) and n.id == name and
                        isinstance(n.ctx, ast.Load))


def _misuse(read: ast.expr, package: Package, tree: ast.Module, index: Index
            ) -> tuple[ast.AST, str, str] | None:
    """(the expression, the operator, the number's type) when ``read`` is compared with or
    computed with a number in a way a list or ``array.array`` refuses."""
    found = operated_with(read, index)
    if found is None:
        return None
    parent, other, symbol = found
    kind = certain_type(other, package, tree, index)
    if kind not in NUMBER_TYPES or symbol == "*" and kind != "float":
        return None  # a sequence times an int repeats it
    assert kind is not None
    return parent, symbol, kind


@rule("PYC043", "sequence-field-as-number", Severity.ERROR,
      fix="Take an element (`msg.ranges[0]`) or a reduction (`min(msg.ranges)`), or convert "
          "with `numpy.array(msg.ranges)` for element-wise work")
def sequence_field_as_number(package: Package) -> Iterator[Hit]:
    """A message's sequence field is compared with, or computed with, a number.

    ## What it does
    Reports a sequence field of a known message (`LaserScan.ranges`, `JointState.position`:
    the fields declared `float32[]`, `string[]`, ...), a slice of one, or a local name bound
    only to one, used with a number in `<`, `>`, `<=`, `>=`, `+`, `-`, `/`, `//`, `%`, `**`,
    or `*` by a float.

    ## Why is this bad?
    rclpy gives a sequence field as an `array.array` (numbers) or a `list` (others), and
    neither compares with or computes with a number: `msg.ranges < 0.5` raises `TypeError:
    '<' not supported between instances of 'array.array' and 'float'`, on the first scan the
    callback gets. (Fixed-size arrays, `float64[9]`, are NumPy arrays and are not reported.)

    ## Example
    ```python
    def on_scan(self, msg):
        if msg.ranges[0:30] < 0.5:
            self.stop()
    ```

    ## Use instead
    ```python
    def on_scan(self, msg):
        if min(msg.ranges[0:30]) < 0.5:
            self.stop()
    ```
    """
    for module, tree, index in installed_trees(package):
        seen: set[int] = set()
        for read, field, kind in _sequence_reads(tree, index, package):
            found = _misuse(read, package, tree, index)
            if found is None or id(found[0]) in seen:
                continue
            seen.add(id(found[0]))
            node, symbol, number = found
            holder = "an array.array" if ARRAY_SEQUENCE.fullmatch(kind) else "a list"
            yield Hit(Span(module.path, node.lineno, node.col_offset + 1),  # type: ignore
                      f"`{ast.unparse(read)}` "
                      f"{'holds' if isinstance(read, ast.Name) else 'is'} the sequence field "
                      f"`{field}`{' or a slice of it' if isinstance(read, ast.Name) else ''} "
                      f"({holder} in "
                      f"rclpy), used with {'an' if number == 'int' else 'a'} {number} in "
                      f"`{symbol}`: Python raises TypeError")
