"""PYC082: a message compared with a plain value (``msg == 'stop'``), never equal."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.message_fields import Message
from pkgtool.model.ast_nodes import last_name, nodes_of_class
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._annotated_messages import annotated_instances
from pkgtool.rules.python._message_instances import Known, callback_instances, known_messages
from pkgtool.rules.python._messages import message_instances
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, installed_trees

_EQUALITY = (ast.Eq, ast.NotEq)
_MEMBERSHIP = (ast.In, ast.NotIn)
_DISPLAYS = (ast.Tuple, ast.List, ast.Set)
_INTEGERS = ("int8", "uint8", "int16", "uint16", "int32", "uint32", "int64", "uint64")
_FLOATS = ("float", "double", "long double")
_FIELD_TYPES = {
    str: ("string", "wstring"),
    bool: ("boolean",),
    int: (*_INTEGERS, *_FLOATS),  # `msg.data == 0` compares a float field too
    float: _FLOATS,
}
"""The field types (as the interface table writes them, IDL's names) a value of each Python
type compares with."""


def _plain_values(node: ast.expr) -> list[ast.Constant]:
    """The str, number or bool literals ``node`` is (or, a literal tuple, list or set, holds),
    a negative number as its number; never ``None`` (a placeholder a message may well
    replace)."""
    items = node.elts if isinstance(node, _DISPLAYS) else [node]
    values = [item.operand if isinstance(item, ast.UnaryOp) and
              isinstance(item.op, (ast.USub, ast.UAdd)) else item for item in items]
    return [value for value in values if isinstance(value, ast.Constant) and
            type(value.value) in _FIELD_TYPES]


def _compared_with(ref: ast.expr, index: Index) -> tuple[str, ast.Constant, str] | None:
    """What ``ref`` is compared with by ``==``, ``!=``, ``in`` or ``not in`` when that is a
    plain value or a display of them (the first comparison, if several): how to name it, its
    first value, and what the comparison does."""
    compare = index.parents.get(id(ref))
    if not isinstance(compare, ast.Compare):
        return None
    operands = [compare.left, *compare.comparators]
    for op, left, right in zip(compare.ops, operands, operands[1:]):
        other = right if left is ref else left if right is ref else None
        if isinstance(op, _EQUALITY) and other is not None and \
                not isinstance(other, _DISPLAYS):
            values = _plain_values(other)
            if values:
                return f"`{ast.unparse(other)}`", values[0], _always(isinstance(op, ast.Eq))
        elif isinstance(op, _MEMBERSHIP) and left is ref and isinstance(right, _DISPLAYS):
            values = _plain_values(right)
            if values and len(values) == len(right.elts):
                return f"any item of `{ast.unparse(right)}`", values[0], \
                    "looking it up in a set raises TypeError (a message cannot be hashed)" \
                    if isinstance(right, ast.Set) else _always(isinstance(op, ast.In))
    return None


def _always(false: bool) -> str:
    return f"the comparison is always {'False' if false else 'True'}"


def _field_meant(message: Message, value: ast.Constant) -> str | None:
    """The one field of ``message`` whose type holds values like ``value``, if one."""
    kinds = _FIELD_TYPES[type(value.value)]
    fields = [name for name, kind in message.fields.items()
              if kind.partition("<")[0] in kinds]
    return fields[0] if len(fields) == 1 else None


@rule("PYC082", "message-compared-with-value", Severity.ERROR,
      fix="Compare the message's field: `msg.data == 'stop'`")
def message_compared_with_value(package: Package) -> Iterator[Hit]:
    """A message is compared with a string, a number or a bool (`msg == 'stop'`).

    ## What it does
    Reports `==`, `!=`, `in` and `not in` between a message instance and a str, int, float
    or bool literal (or a literal tuple, list or set of them): `msg == 'stop'` where `msg`
    is what a subscription's callback gets, or `self.state != 'idle'` where the callback
    stored its message in `self.state`. A message is certain where PYC019 is certain of it
    (a callback's parameter, a local variable or `self.x` made by one message class, a
    service's response), but for a parameter annotated with a message class that is no
    callback's (its callers may pass a str), and for a callback's parameter when the module
    also calls the callback itself (`self.on_command('stop')`); a comparison with `None` is
    left alone
    (`self.last` may still be its placeholder). The message names the field meant when only
    one field of the message holds values of the literal's type (`data` of
    `std_msgs/msg/String`).

    ## Why is this bad?
    A generated message class is equal only to another message of its class: compared with
    a str or a number, `==` is always False and `!=` always True, whatever the message
    holds. The branch meant for the command never runs, and nothing fails to say so. A
    message cannot be hashed either: `msg in {'a', 'b'}` raises TypeError.

    ## Example
    ```python
    def on_command(self, msg):
        if msg == 'stop':
            self.halt()
    ```

    ## Use instead
    ```python
    def on_command(self, msg):
        if msg.data == 'stop':
            self.halt()
    ```
    """
    for module, tree, index in installed_trees(package):
        if not _compares(tree):
            continue  # no `==`, `!=`, `in`: no instance to look for
        known = known_messages(package, index)
        compared = [(instance.message, ref, found)
                    for instance in message_instances(package, tree, index, known)
                    for ref in instance.refs if (found := _compared_with(ref, index))]
        hinted = _maybe_not_messages(tree, index, known) if compared else set()
        seen: set[int] = set()
        for message, ref, (named, value, verdict) in compared:
            if id(ref) in hinted or id(ref) in seen:
                continue
            seen.add(id(ref))
            shown = ast.unparse(ref)
            field = _field_meant(message, value)
            yield Hit(Span(module.path, ref.lineno, ref.col_offset + 1),
                      f"`{shown}` is a `{message.name}` message, never equal to "
                      f"{named}: {verdict}",
                      f"Compare the field: `{shown}.{field}`" if field else
                      f"Compare one of its fields: {_fields(message)}")


def _maybe_not_messages(tree: ast.Module, index: Index, known: Known) -> set[int]:
    """Ids of the reads of parameters that may hold something else than a message: those
    holding one by their annotation alone (an annotation does not make callers pass a
    message), and a callback's that the module also calls itself (``self.on_command('stop')``)."""
    called = {last_name(call.func) for call in index.calls}
    received = [ref for instance in callback_instances(tree, index, known)
                for ref in instance.refs]
    found = {id(ref) for ref in received
             if (function := index.enclosing_function(ref, through_lambdas=False)) is not None
             and function.name in called}
    passed = {id(ref) for ref in received}
    found.update(id(ref) for instance in annotated_instances(tree, index, known)
                 for ref in instance.refs if id(ref) not in passed)
    return found


def _compares(tree: ast.Module) -> bool:
    """True when the module compares anything by ``==``, ``!=``, ``in`` or ``not in``."""
    return any(isinstance(op, (*_EQUALITY, *_MEMBERSHIP))
               for compare in nodes_of_class(tree, ast.Compare)
               for op in compare.ops)  # type: ignore[attr-defined]


def _fields(message: Message) -> str:
    return ", ".join(f"`{name}`" for name in message.fields) or "it has none"
