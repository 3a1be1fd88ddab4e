"""PYC080: a message indexed like a sequence (``odom.pose.pose.position[0]``)."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.message_fields import Message, nested_message
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._derived_messages import derived_instances
from pkgtool.rules.python._message_instances import Instance, fields_taken, known_messages
from pkgtool.rules.python._messages import message_instances
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, installed_trees


@rule("PYC080", "message-subscripted", Severity.ERROR,
      fix="Read the message's fields by name (see the message)")
def message_subscripted(package: Package) -> Iterator[Hit]:
    """A message, or a field holding one message, is indexed like a list or a tuple.

    ## What it does
    Reports `value[...]` (read, set or deleted) where `value` is certainly one message: an
    instance PYC019 knows (a fresh message, a callback's message, a service's response, a name
    bound to one of their fields or elements, ...) or a field of one whose type is one message,
    not a sequence: `odom.pose.pose.position[0]` (a `Point`), `msg.orientation[3]` (a
    `Quaternion`), `t.transform.translation[:2]` (a `Vector3`). Fields holding sequences or
    arrays (`msg.ranges[0]`, `msg.poses[-1]`, `msg.covariance[0]`) are sequences and never
    reported.

    ## Why is this bad?
    Generated message classes have named fields and no `__getitem__`: the line raises
    `TypeError: 'Point' object is not subscriptable` when it runs, usually in a callback where
    the executor logs it and the node stops doing its job. A `Point` is not the `[x, y, z]`
    list some other APIs use.

    ## Example
    ```python
    x = msg.pose.pose.position[0]
    ```

    ## Use instead
    ```python
    x = msg.pose.pose.position.x
    ```
    """
    for module, tree, index in installed_trees(package):
        held = message_instances(package, tree, index, known_messages(package, index))
        seen: set[int] = set()
        for instance in (*held, *derived_instances(held, tree, index)):
            for value, message in _indexed(instance, index):
                if id(value) not in seen:
                    seen.add(id(value))
                    yield _hit(module.path, value, message, index)


def _indexed(instance: Instance[Message], index: Index
             ) -> Iterator[tuple[ast.expr, Message]]:
    """The expressions holding one message that are subscripted: the instance itself, and
    its message-typed fields followed while their class is certain."""
    for ref in instance.refs:
        if _subscripted(ref, index):
            yield ref, instance.message
    for node, message, path in fields_taken(instance, index):
        nested = nested_message(message, node.attr) if path not in instance.stored else None
        if nested is not None and _subscripted(node, index):
            yield node, nested


def _subscripted(value: ast.expr, index: Index) -> bool:
    """True when ``value`` is the object of a subscript (``value[0]``)."""
    parent = index.parents.get(id(value))
    return isinstance(parent, ast.Subscript) and parent.value is value


_ORDERED = {"geometry_msgs/msg/Point": "xyz", "geometry_msgs/msg/Point32": "xyz",
            "geometry_msgs/msg/Vector3": "xyz", "geometry_msgs/msg/Quaternion": "xyzw"}
"""Messages whose fields other APIs hold as a list in this order (``[x, y, z]``)."""


def _hit(path: str, value: ast.expr, message: Message, index: Index) -> Hit:
    """The finding for ``value[...]``, ``value`` an instance of ``message``: the field meant
    when the index is a literal position of a point, vector or quaternion."""
    fields = ", ".join(f"`.{name}`" for name in message.fields)
    shown = ast.unparse(value)
    subscript = index.parents[id(value)]
    position = subscript.slice.value if isinstance(subscript, ast.Subscript) and \
        isinstance(subscript.slice, ast.Constant) else None
    order = _ORDERED.get(message.name, "")
    meant = order[position] if isinstance(position, int) and not isinstance(position, bool) \
        and 0 <= position < len(order) else None
    return Hit(Span(path, value.lineno, value.col_offset + 1),
               f"`{shown}` is one `{message.name}` message, not a sequence: indexing it raises "
               "TypeError (messages have no items)",
               f"Write `{shown}.{meant}`" if meant else
               f"Read its fields by name: {fields}" if fields else None)
