"""PYC025: a value of the wrong type given to a message field (``twist.linear.x = 1``)."""

from __future__ import annotations

import ast
import re
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.message_fields import MESSAGE_TYPE, Message, nested_message
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._field_reads import ARRAY_SEQUENCE
from pkgtool.rules.python._message_instances import Instance, known_messages
from pkgtool.rules.python._messages import message_instances
from pkgtool.rules.python._own_callees import parameter_names
from pkgtool.rules.python._rclpy_objects import TIME, object_class
from pkgtool.rules.python._value_types import certain_type
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, installed_trees

_ACCEPTED = (
    (re.compile(r"float|double"), frozenset({"float"}), "a float (`1.0`, not `1`)"),
    (re.compile(r"u?int(8|16|32|64)"), frozenset({"int", "bool"}), "an int"),
    (re.compile(r"boolean"), frozenset({"bool"}), "a bool (`True`/`False`)"),
    (re.compile(r"w?string(<=?\d+>)?"), frozenset({"str"}), "a str"),
)
"""rosidl basic field types, the literal types rclpy's message classes accept for them, and
how to say it."""


def _wanted(kind: str) -> tuple[frozenset[str], str] | None:
    """The literal types a field of rosidl type ``kind`` accepts, and how to say it."""
    return next(((accepted, said) for pattern, accepted, said in _ACCEPTED
                 if pattern.fullmatch(kind)), None)


_ROS_TIMES = {"builtin_interfaces/Time": "rclpy.time.Time",
              "builtin_interfaces/Duration": "rclpy.duration.Duration"}
"""Message fields of time types, and the rclpy class people give them instead."""
TO_MSG = "Convert it with `.to_msg()`"
_FIXES = {"rclpy.time.Time": TO_MSG, "rclpy.duration.Duration": TO_MSG}


def _not_a_message(kind: str, value: ast.expr, given: str | None, package: Package,
                   tree: ast.Module, index: Index) -> str | None:
    """What ``value`` (certainly of type ``given``, if not None) is (``float``,
    ``rclpy.time.Time``) when it is certainly not a message for a field of message type
    ``kind``; None when it may be one."""
    if not MESSAGE_TYPE.fullmatch(kind):
        return None
    if given in ("int", "float", "bool", "str", "list", "tuple", "dict", "set"):
        return given
    wrong = _ROS_TIMES.get(kind)
    if wrong is None or _parameter(value, index):
        return None  # an annotation promises nothing of what callers pass
    return wrong if _clock_reading(value) and wrong == TIME or \
        object_class(value, package, tree, index) == wrong else None


def _clock_reading(value: ast.expr) -> bool:
    """True for ``<anything>.get_clock().now()``: an rclpy ``Time``."""
    func = value.func if isinstance(value, ast.Call) else None
    return isinstance(func, ast.Attribute) and func.attr == "now" and \
        isinstance(func.value, ast.Call) and isinstance(func.value.func, ast.Attribute) and \
        func.value.func.attr == "get_clock"


def _parameter(value: ast.expr, index: Index) -> bool:
    """True for a name that is a parameter of the function it is read in."""
    if not isinstance(value, ast.Name):
        return False
    function = index.enclosing_function(value)
    return function is not None and value.id in parameter_names(function.args)


def float_fix(value: ast.expr, given: str | None) -> str | None:
    """How to give a float field the int ``value`` (of type ``given``): ``Write `1.0``` for a
    literal (``1``, ``-2``), ``Write `float(turns)``` for a name or attribute; else None."""
    number = value.operand if isinstance(value, ast.UnaryOp) and \
        isinstance(value.op, (ast.USub, ast.UAdd)) else value
    if isinstance(number, ast.Constant) and type(number.value) is int:
        return f"Write `{ast.unparse(value)}.0`"
    if given == "int" and isinstance(value, (ast.Name, ast.Attribute)):
        return f"Write `float({ast.unparse(value)})`"
    return None


def _stores(instance: Instance[Message], index: Index
            ) -> Iterator[tuple[str, str, ast.expr]]:
    """(target, field type, value) of ``instance.a.b = value`` assignments to a field."""
    for use in instance.uses:
        node: ast.AST | None = use
        message: Message | None = instance.message
        path: tuple[str, ...] = ()
        while isinstance(node, ast.Attribute) and message is not None:
            kind = message.fields.get(node.attr)
            parent = index.parents.get(id(node))
            if kind is None:
                break
            if isinstance(parent, ast.Assign) and parent.targets == [node]:
                yield ast.unparse(node), kind, parent.value
                break
            path = (*path, node.attr)
            message = None if path in instance.stored else nested_message(message, node.attr)
            node = parent if isinstance(parent, ast.Attribute) and parent.value is node else None


def _how(value: ast.expr) -> str:
    """How a value that is no literal is known to have its type."""
    if isinstance(value, ast.Name):
        return ": what it is assigned in its function gives one"
    return ": every assignment to it gives one" if isinstance(value, ast.Attribute) else ""


@rule("PYC025", "field-value-type", Severity.ERROR,
      fix="Write the value with the field's type: `1.0` for a float64, `True` for a bool")
def field_value_type(package: Package) -> Iterator[Hit]:
    """A message field is given a value of another type than the field's.

    ## What it does
    For the message instances PYC019 is certain of (and the keyword arguments of known
    message constructors), reports a literal assigned to a basic field whose type does not
    accept it: an int, bool, string or `None` for a `float32`/`float64` field
    (`twist.linear.x = 1`), a float, string or `None` for an integer field, anything but
    `True`/`False` for a `bool` field, anything but a string for a `string` field. Values
    judged are literals (`1`, `-2`, `'a'`, `None`), the results of the builtins `int()`,
    `float()`, `str()`, `bool()` and `len()` in modules that bind none of these names
    themselves (`msg.data = len(items)` in a `string` field), local names every assignment
    of which in their function gives a value of one such type (`n = 0`, `n += 1`), and
    attributes `self.x` of a class deriving from rclpy's `Node` alone when every assignment
    to an attribute `x` in the package's installed modules does (`self.count = 0`); other
    expressions never. A field that holds a message is reported when given a number, bool
    or string (`cmd.linear = 0.5`), a sequence of numbers (`float64[]`, stored as an
    `array.array`) when given a number or a string, and a `builtin_interfaces/Time` or
    `Duration` field when given
    rclpy's own `Time` or `Duration` (`header.stamp = self.get_clock().now()`, without
    `.to_msg()`).

    ## Why is this bad?
    With field checks on (always on Humble, `ROS_PYTHON_CHECK_FIELDS=1` since Iron) the
    assignment raises `AssertionError: The 'x' field must be of type 'float'`. Without them
    (Jazzy's default) the value reaches the C conversion unchecked: an int in a float field
    is published as garbage, `1` in a bool field as `False`, a number in a string field
    makes `publish()` raise. A message field given anything but a message of its type fails
    the same checks, or `publish()` when rclpy converts the message. A number or a string
    given to a sequence of numbers fails at once, checks or not: rclpy converts it to an
    `array.array` (`TypeError: 'float' object is not iterable`).

    ## Example
    ```python
    cmd = Twist()
    cmd.linear.x = 1
    ```

    ## Use instead
    ```python
    cmd = Twist()
    cmd.linear.x = 1.0
    ```
    """
    for module, tree, index in installed_trees(package):
        known = known_messages(package, index)
        found: list[tuple[str, str, ast.expr]] = []
        for instance in message_instances(package, tree, index, known):
            found.extend(_stores(instance, index))
        for call in index.calls:
            message = known(call.func)
            found.extend((f"{ast.unparse(call.func)}({k.arg}=...)", message.fields[k.arg],
                          k.value) for k in call.keywords
                         if message is not None and k.arg in message.fields)
        for target, kind, value in found:
            wanted, given = _wanted(kind), certain_type(value, package, tree, index)
            if wanted is not None and given is not None and given not in wanted[0]:
                yield Hit(Span(module.path, value.lineno, value.col_offset + 1),
                          f"`{target}` is a `{kind}` field but is given `{ast.unparse(value)}`"
                          f" ({given}{_how(value)}): rclpy wants {wanted[1]}",
                          float_fix(value, given) if wanted[0] == {"float"} else None)
            elif ARRAY_SEQUENCE.fullmatch(kind) and given in ("int", "float", "bool", "str"):
                yield Hit(Span(module.path, value.lineno, value.col_offset + 1),
                          f"`{target}` is a `{kind}` field but is given `{ast.unparse(value)}`"
                          f" ({given}{_how(value)}): rclpy makes an array of it and raises "
                          "TypeError", f"Give a list: `[{ast.unparse(value)}]`"
                          if given != "str" else None)
            elif (problem := _not_a_message(kind, value, given, package, tree, index)) \
                    is not None:
                yield Hit(Span(module.path, value.lineno, value.col_offset + 1),
                          f"`{target}` holds a `{kind}` message but is given "
                          f"`{ast.unparse(value)}` ({problem})", _FIXES.get(problem))
