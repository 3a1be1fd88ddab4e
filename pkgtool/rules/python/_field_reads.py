"""The fields of known messages that code reads, with their rosidl types (PYC042, PYC043).

A read is the outermost attribute of a path on a message instance (``msg.linear.x``, not
``msg.linear``, when ``linear`` holds a nested message; ``msg.data`` in ``msg.data.upper()``),
as :mod:`._message_instances` finds the instances.
"""

from __future__ import annotations

import ast
import re

from pkgtool.knowledge.message_fields import Message, nested_message
from pkgtool.model.package import Package
from pkgtool.records import record
from pkgtool.rules.python._message_instances import kept, known_messages
from pkgtool.rules.python._messages import message_instances
from pkgtool.rules.python._value_types import certain_type
from pkgtool.rules.syntax_trees import Index
from pkgtool.lazy_regex import lazy_pattern

_PYTHON_TYPES = ((re.compile(r"float|double"), "float"),
                 (re.compile(r"u?int(8|16|32|64)"), "int"),
                 (re.compile(r"boolean"), "bool"),
                 (re.compile(r"w?string(<=?\d+>)?"), "str"))
"""rosidl basic types and the Python type rclpy gives a field of each."""
ARRAY_SEQUENCE = lazy_pattern(r"sequence<(u?int(8|16|32|64)|float|double)[,>].*")
"""Sequences rclpy stores as an ``array.array`` (converting what it is given); the others
(strings, bools, octets, messages) are lists."""
ORDER = {ast.Lt: "<", ast.Gt: ">", ast.LtE: "<=", ast.GtE: ">="}
"""The ordering comparisons, by operator class."""
ARITHMETIC = {ast.Add: "+", ast.Sub: "-", ast.Div: "/", ast.FloorDiv: "//", ast.Mod: "%",
              ast.Pow: "**", ast.Mult: "*"}
"""The arithmetic operators, by operator class (``@`` left out)."""


def operated_with(node: ast.expr, index: Index) -> tuple[ast.expr, ast.expr, str] | None:
    """(the operation, the other operand, the operator) when ``node`` is an operand of an
    ordering comparison of two (``<``, ``>=``, ...) or of arithmetic; else None."""
    parent = index.parents.get(id(node))
    if isinstance(parent, ast.Compare) and len(parent.ops) == 1 and \
            type(parent.ops[0]) in ORDER:
        other = parent.comparators[0] if parent.left is node else parent.left
        return parent, other, ORDER[type(parent.ops[0])]
    if isinstance(parent, ast.BinOp) and type(parent.op) in ARITHMETIC:
        other = parent.right if parent.left is node else parent.left
        return parent, other, ARITHMETIC[type(parent.op)]
    return None


@record
class FieldRead:
    """A read of the field ``field`` (``pkg/msg/Type.name``) of rosidl type ``kind``."""

    node: ast.Attribute
    field: str
    kind: str

    @property
    def python_type(self) -> str | None:
        """The Python type rclpy gives the field (``float``, ``int``, ``bool``, ``str``), or
        None for sequences, arrays, nested messages and other types."""
        return next((name for pattern, name in _PYTHON_TYPES if pattern.fullmatch(self.kind)),
                    None)


def value_type(value: ast.expr, reads: dict[int, FieldRead], package: Package,
               tree: ast.Module, index: Index) -> str | None:
    """The type ``value`` certainly has: a message field's (``reads``: the tree's
    :func:`field_reads`), else :func:`~._value_types.certain_type`'s."""
    read = reads.get(id(value))
    return read.python_type if read is not None else certain_type(value, package, tree, index)


def field_reads(tree: ast.Module, index: Index, package: Package) -> dict[int, FieldRead]:
    """The field reads of ``tree`` (a module of ``package``) by ``id`` of their attribute
    node, worked out once per tree (kept with its message instances)."""
    return kept(tree, "field reads", lambda: _field_reads(tree, index, package))


def _field_reads(tree: ast.Module, index: Index, package: Package) -> dict[int, FieldRead]:
    found: dict[int, FieldRead] = {}
    for instance in message_instances(package, tree, index, known_messages(package, index)):
        for use in instance.uses:
            read = _read(instance.message, use, index)
            if read is not None:
                found[id(read.node)] = read
    return found


def _read(message: Message, use: ast.Attribute, index: Index) -> FieldRead | None:
    """The read of ``use``'s path (``msg.a.b``) down to its last field, when it is a read."""
    current, holder = use, message
    while True:
        parent = index.parents.get(id(current))
        if isinstance(parent, ast.Attribute) and parent.value is current:
            nested = nested_message(holder, current.attr)
            if nested is not None:
                current, holder = parent, nested
                continue  # else an attribute of the field's value: the field is read
        kind = holder.fields.get(current.attr)
        augmented = isinstance(parent, ast.AugAssign) and parent.target is current
        if kind is None or not isinstance(current.ctx, ast.Load) and not augmented:
            return None  # a store, but `msg.data += x` reads the field first
        return FieldRead(current, f"{holder.name}.{current.attr}", kind)
