"""PYC045: a field holding a message computed with, or ordered like, a number."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.message_fields import MESSAGE_TYPE, message_of, nested_message
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._field_reads import FieldRead, field_reads, operated_with, value_type
from pkgtool.rules.python._value_types import NUMBER_TYPES
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, installed_trees

_SIGNS = {ast.USub: "-", ast.UAdd: "+", ast.Invert: "~"}


def _kind(value: ast.expr, reads: dict[int, FieldRead], package: Package, tree: ast.Module,
          index: Index) -> str | None:
    """What ``value`` certainly is, for this rule: ``message`` (a field holding one), a number
    type (a number field's, or :func:`certain_type`'s), else None."""
    read = reads.get(id(value))
    if read is not None and MESSAGE_TYPE.fullmatch(read.kind):
        return "message"
    return value_type(value, reads, package, tree, index)


def _misuse(read: FieldRead, reads: dict[int, FieldRead], package: Package, tree: ast.Module,
            index: Index) -> tuple[ast.expr, str, str | None] | None:
    """(the expression, the operator, the other operand's kind: None for a unary one) when
    the message ``read`` gives is an operand of an operator no message class defines, the
    other operand certainly a number or a message."""
    parent = index.parents.get(id(read.node))
    if isinstance(parent, ast.UnaryOp) and type(parent.op) in _SIGNS:
        return parent, _SIGNS[type(parent.op)], None
    found = operated_with(read.node, index)
    if found is None:
        return None
    operation, other, symbol = found
    kind = _kind(other, reads, package, tree, index)
    if kind not in NUMBER_TYPES and kind != "message":
        return None
    return operation, symbol, kind


def _fields_of(read: FieldRead, package: Package) -> str:
    """`` (its fields: x, y, z)`` for the message class the read field holds, when known."""
    holder, _, name = read.field.rpartition(".")
    message = message_of(holder.replace("/", "."), package.context.distro)
    nested = nested_message(message, name) if message is not None else None
    if nested is None or not nested.fields:
        return ""
    return f" (its fields: {', '.join(f'`{f}`' for f in nested.fields)})"


@rule("PYC045", "message-field-as-number", Severity.ERROR,
      fix="Use a number field of the nested message (`msg.linear.x`, `msg.header.stamp.sec`)")
def message_field_as_number(package: Package) -> Iterator[Hit]:
    """A field that holds a message is computed with, or ordered like, a number.

    ## What it does
    Reports a field of a known message that holds another message (`Twist.angular`, a
    `Vector3`; `Header.stamp`, a `Time`; `Odometry.pose`) used with `+`, `-`, `*`, `/`,
    `//`, `%`, `**`, `<`, `>`, `<=` or `>=` where the other side is certainly a number (a
    literal, a number field, a name only ever bound to one) or another such field, and one
    negated (`-msg.angular`).

    ## Why is this bad?
    The message classes rclpy generates define no arithmetic and no ordering:
    `msg.linear.x + msg.angular` raises `TypeError: unsupported operand type(s) for +:
    'float' and 'Vector3'` on the first message the callback gets. The number meant is a
    field of the nested message (`msg.angular.z`).

    ## Example
    ```python
    def on_cmd(self, msg):
        speed = msg.linear.x + msg.angular
    ```

    ## Use instead
    ```python
    def on_cmd(self, msg):
        speed = msg.linear.x + msg.angular.z
    ```
    """
    for module, tree, index in installed_trees(package):
        reads = field_reads(tree, index, package)
        seen: set[int] = set()
        for read in reads.values():
            if not MESSAGE_TYPE.fullmatch(read.kind):
                continue
            found = _misuse(read, reads, package, tree, index)
            if found is None or id(found[0]) in seen:
                continue
            seen.add(id(found[0]))
            node, symbol, other = found
            used = "negated" if other is None and symbol == "-" else \
                f"given to unary `{symbol}`" if other is None else \
                f"used with {'an' if other == 'int' else 'a'} {other} in `{symbol}`" \
                if other != "message" else f"used with another message in `{symbol}`"
            yield Hit(Span(module.path, node.lineno, node.col_offset + 1),
                      f"`{ast.unparse(read.node)}` is the field `{read.field}`, a "
                      f"`{read.kind}` message{_fields_of(read, package)}, {used}: message "
                      f"classes define no arithmetic or ordering, Python raises TypeError")
