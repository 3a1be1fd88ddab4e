"""PYC053: a message field's value used as what its type is not (``msg.data.append``)."""

from __future__ import annotations

import array
import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._field_reads import ARRAY_SEQUENCE, FieldRead, field_reads
from pkgtool.rules.python._message_instances import known_messages
from pkgtool.rules.python._messages import message_instances
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, installed_trees

_TYPES: dict[str, type] = {"str": str, "int": int, "float": float, "bool": bool}
"""The Python types rclpy gives basic fields, by name."""


def _value_type(read: FieldRead) -> tuple[str, type] | None:
    """(name, class) of what rclpy gives the field: a basic value, an ``array.array`` for a
    sequence of numbers, a ``list`` for other sequences; None for the rest (fixed-size
    arrays are NumPy arrays, nested messages have their own fields)."""
    if read.python_type in _TYPES:
        return read.python_type, _TYPES[read.python_type]
    if ARRAY_SEQUENCE.fullmatch(read.kind):
        return "array.array", array.array
    if read.kind.startswith("sequence<"):
        return "list", list
    return None


def _misuse(read: FieldRead, index: Index) -> str | None:
    """What Python raises for the use of ``read``'s value, if it certainly raises."""
    found = _value_type(read)
    if found is None:
        return None
    name, kind = found
    parent = index.parents.get(id(read.node))
    if isinstance(parent, ast.Attribute) and parent.value is read.node and \
            not hasattr(kind, parent.attr):
        return f"AttributeError: '{name}' object has no attribute '{parent.attr}'"
    if isinstance(parent, ast.Subscript) and parent.value is read.node:
        if kind in (int, float, bool):
            return f"TypeError: '{name}' object is not subscriptable"
        if kind is str and not isinstance(parent.ctx, ast.Load):
            return "TypeError: 'str' object does not support item assignment"
    return None


def _container_use(ref: ast.expr, index: Index) -> str | None:
    """What Python raises when the message ``ref`` reads is measured, indexed or iterated."""
    parent = index.parents.get(id(ref))
    if isinstance(parent, ast.Call) and isinstance(parent.func, ast.Name) and \
            parent.func.id == "len" and parent.args == [ref] and "len" not in index.bound:
        return "has no len()"
    if isinstance(parent, ast.Subscript) and parent.value is ref:
        return "is not subscriptable"
    if isinstance(parent, (ast.For, ast.comprehension)) and parent.iter is ref:
        return "is not iterable"
    return None


def _messages_misused(path: str, package: Package, tree: ast.Module, index: Index
                      ) -> Iterator[Hit]:
    """A message itself (not a field of it) measured, indexed or iterated."""
    for instance in message_instances(package, tree, index, known_messages(package, index)):
        for ref in instance.refs:
            problem = _container_use(ref, index)
            if problem:
                name = instance.message.name.rpartition("/")[2]
                said = f"object of type '{name}' has no len()" if problem == "has no len()" \
                    else f"'{name}' object {problem}"
                yield Hit(Span(path, ref.lineno, ref.col_offset + 1),
                          f"`{ast.unparse(ref)}` is a `{instance.message.name}` message, which "
                          f"{problem}: Python raises TypeError ({said})",
                          "Use one of its fields (`msg.data`, `msg.ranges`)")


@rule("PYC053", "field-value-misused", Severity.ERROR,
      fix="Use what the field's type has: `msg.data + '!'` for a str, `len(msg.ranges)`, "
          "`numpy.asarray(msg.ranges)` for array work")
def field_value_misused(package: Package) -> Iterator[Hit]:
    """A message field's value is used as what its type is not.

    ## What it does
    Reports, on a field of a known message (as PYC019 finds them), an attribute the value's
    type does not have (`msg.data.append('!')` on a str, `msg.ranges.size` or
    `msg.ranges.shape` on the `array.array` rclpy gives a `float32[]`, `msg.linear.x.round()`),
    an index into a number (`msg.linear.x[0]`), and an item assigned into a str
    (`msg.data[0] = 'H'`). Python's own types answer (`hasattr(str, 'append')`). Also a
    message itself measured, indexed or iterated (`len(msg)`, `msg[0]`, `for r in msg:`).

    ## Why is this bad?
    rclpy gives a field a plain Python value: a str, an int, a float, a bool, an
    `array.array` for a sequence of numbers (not a NumPy array), a list for other
    sequences. NumPy habits (`.size`, `.shape`) and list habits on strings raise
    `AttributeError` or `TypeError` in the callback, on the first message.

    ## Example
    ```python
    def on_scan(self, msg):
        if msg.ranges.size == 0:
            return
    ```

    ## Use instead
    ```python
    def on_scan(self, msg):
        if len(msg.ranges) == 0:
            return
    ```
    """
    for module, tree, index in installed_trees(package):
        yield from _messages_misused(module.path, package, tree, index)
        for read in field_reads(tree, index, package).values():
            problem = _misuse(read, index)
            if problem:
                yield Hit(Span(module.path, read.node.lineno, read.node.col_offset + 1),
                          f"`{ast.unparse(read.node)}` is the field `{read.field}`: Python "
                          f"raises {problem}")
