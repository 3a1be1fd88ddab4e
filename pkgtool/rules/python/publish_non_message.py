"""PYC020: a publisher given something that is certainly not a message of its type, a
service or action client something that is certainly no request or goal."""

from __future__ import annotations

import ast
from collections.abc import Callable, Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.message_fields import Message
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.records import record
from pkgtool.rules.node_api import (ACTION_CLIENTS, PARAMETERS, argument, literal_type,
                                    unpacks)
from pkgtool.rules.python._assignments import made_class
from pkgtool.rules.python._callbacks import execute_callbacks
from pkgtool.rules.python._message_instances import (Instance, Known, attribute_instances,
                                                     known_messages, local_instances)
from pkgtool.rules.python._messages import message_instances
from pkgtool.rules.python._value_types import certain_type
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, installed_trees
from pkgtool.lazy_regex import lazy_pattern

_ACCEPTED = frozenset({"bytes", "NoneType", "ellipsis"})
"""Literals never reported: ``bytes`` (published raw, serialized) and ``None``/``...``."""
_BASIC = lazy_pattern(r"boolean|float|double|u?int(?:8|16|32|64)|w?string(?:<\d+>)?")
"""Field types whose values are plain Python values (``bool``, ``float``, ``int``, ``str``)."""


@record
class Publisher:
    """A publisher made by rclpy's ``create_publisher`` (with its message class if known),
    or a service or action client: what it sends, and the methods sending it."""

    message: Message | None
    sends: str = "message"
    methods: tuple[str, ...] = ("publish",)


_CLIENT = Publisher(None, "request", ("call", "call_async"))
_ACTION_CLIENT = Publisher(None, "goal", ("send_goal", "send_goal_async"))
_GOAL_HANDLE = Publisher(None, "feedback message", ("publish_feedback",))
_SENT = {"msg", "request", "goal", "feedback"}
"""The names of the sent value's parameter in ``publish``, ``call*``, ``send_goal*`` and
``publish_feedback``."""
_SENDER = {"message": "publisher", "request": "client", "goal": "action client",
           "feedback message": "action"}
_INSTANCE = "Send an instance: `Trigger.Request()` to a service, `Fibonacci.Goal()` to an action"
_FIXES = {"message": None, "request": _INSTANCE, "goal": _INSTANCE,
          "feedback message": "Publish an instance of the action's feedback "
                              "(`Fibonacci.Feedback()`, its fields set)"}
"""The fix of a finding, by what the call sends."""


def _publisher_maker(known: Known, index: Index) -> Callable[[ast.Call], Publisher | None]:
    """What a call makes when it is ``x.create_publisher(Type, ...)`` (rclpy's), or
    ``x.create_client(...)``, or rclpy's ``ActionClient(...)``."""
    def make(call: ast.Call) -> Publisher | None:
        if unpacks(call):
            return None
        if index.qualified(call.func) in ACTION_CLIENTS:
            return _ACTION_CLIENT
        method = call.func.attr if isinstance(call.func, ast.Attribute) else None
        if method == "create_client":
            return _CLIENT
        if method != "create_publisher" or \
                any(k.arg == "publisher_class" for k in call.keywords):
            return None
        kind = argument(call, PARAMETERS["create_publisher"], "msg_type")
        return Publisher(known(kind) if kind is not None else None)
    return make


def _published(ref: ast.expr, index: Index, methods: tuple[str, ...]
               ) -> tuple[str, ast.expr] | None:
    """The method and the sent argument of ``ref.<method>(argument, ...)``, when ``ref`` is
    so used with one of ``methods``."""
    method = index.parents.get(id(ref))
    call = index.parents.get(id(method))
    if not (isinstance(method, ast.Attribute) and method.attr in methods
            and isinstance(call, ast.Call) and call.func is method) or unpacks(call):
        return None
    first = call.args[0] if call.args else next(
        (k.value for k in call.keywords if k.arg in _SENT), None)
    return (method.attr, first) if first is not None and \
        (method.attr != "publish" or len(call.args) + len(call.keywords) == 1) else None


def _publish_call(ref: ast.expr, index: Index) -> ast.Call | None:
    """The call ``ref.publish(...)`` when ``ref`` is so used (no ``*args``/``**kwargs``)."""
    method = index.parents.get(id(ref))
    call = index.parents.get(id(method))
    return call if isinstance(method, ast.Attribute) and method.attr == "publish" and \
        isinstance(call, ast.Call) and call.func is method and not unpacks(call) else None


def _second(ref: ast.expr, index: Index) -> ast.expr | None:
    """The second positional argument of ``ref.publish(a, b, ...)``, if so called."""
    call = _publish_call(ref, index)
    return call.args[1] if call is not None and len(call.args) > 1 else None


def _not_a_message(value: ast.expr, publisher: Publisher,
                   messages: list[Instance[Message]], wrong: str | None,
                   made: Message | None = None) -> str | None:
    """Why ``value`` (certainly of type ``wrong``, if not None; a call making the known
    message ``made``, if not None) is certainly no message of the ``publisher``'s type, if
    it is."""
    expected = publisher.message
    if made is not None and expected is not None and made.name != expected.name:
        return f"a `{made.name}`, the publisher's type is `{expected.name}`"
    if wrong == "type":
        return "the class itself, not an instance of it (`()` is missing where it is made)"
    if isinstance(value, ast.Compare) or \
            isinstance(value, ast.UnaryOp) and isinstance(value.op, ast.Not):
        return "a truth value, not a message (build the message and set its field to it)"
    if wrong is not None and wrong not in _ACCEPTED:
        return f"a literal of type `{wrong}`" if literal_type(value) else \
            f"a value of type `{wrong}` (what it is assigned gives one)"
    for instance in messages:
        if any(use is value for use in instance.uses) and isinstance(value, ast.Attribute):
            kind = instance.message.fields.get(value.attr, "")
            if _BASIC.fullmatch(kind):
                return f"the `{kind}` field `{value.attr}` of a `{instance.message.name}`"
        if expected is not None and instance.message.name != expected.name and any(
                ref is value for ref in instance.refs):
            return f"a `{instance.message.name}`, the publisher's type is `{expected.name}`"
    return None


@rule("PYC020", "publish-non-message", Severity.ERROR,
      fix="Publish a message of the publisher's type (`msg = String(); msg.data = ...`)")
def publish_non_message(package: Package) -> Iterator[Hit]:
    """A publisher is given a value that is certainly not a message of its type.

    ## What it does
    Checks `publish(...)` calls on publishers certainly made by rclpy's `create_publisher`
    (a local variable bound once by `pub = node.create_publisher(...)`, or `self.pub` in a
    class whose methods all assign it that way when nothing else in the module stores an
    attribute `pub`; not with `publisher_class=`, `*args` or `**kwargs`, nor in modules
    defining their own `create_publisher`), in installed modules. Reports a string, number,
    boolean, f-string or list, tuple, dict or set literal (`pub.publish('hello')`); a plain
    field (`string`, `float`, `int32`, ...) of a message instance PYC019 is certain of
    (`pub.publish(msg.data)`); a comparison or a `not` (`pub.publish(level < limit)`: a
    truth value, not a `Bool`); a local name or a node's `self.x` every assignment of which
    gives a literal of one such type (`text = 'hi'`; PYC025 says which); a message class
    itself (`pub.publish(String)`, or `msg = String` without `()`); and such an
    instance, or a call making one, of another known message class than the publisher's
    (`create_publisher(String, ...)` then `publish(Float32(data=1.0))`). Also checks
    the request given to `call()` and `call_async()` of a client made by `create_client`,
    and the goal given to `send_goal()` and `send_goal_async()` of rclpy's `ActionClient`
    (held the same ways), for literals and classes (`call_async(Trigger.Request)`).
    `bytes` (published as serialized data), other names, calls and unknown types are never
    reported. A `publish()` given a second positional argument (`pub.publish(String, msg)`)
    or no message at all (`pub.publish()`) or the message's fields as keywords (rospy's
    `pub.publish(data='hi')`) is reported too, and so is what an action server's
    execute callback gives its goal handle's `publish_feedback()` when it is such a literal
    or class, or certainly an instance of a message or of another class of an action
    (`Fibonacci.Result()` where `Fibonacci.Feedback()` belongs).

    ## Why is this bad?
    `Publisher.publish` raises `TypeError: Expected <class 'std_msgs.msg._string.String'>,
    got <class 'str'>` for anything that is not an instance of the publisher's message class
    (or `bytes`): the node dies the first time it publishes, often inside a timer callback.
    A client's `call_async()` and an action client's `send_goal_async()` raise `TypeError`
    the same way for anything but an instance of the request or goal class.

    ## Example
    ```python
    self.pub = self.create_publisher(String, 'chatter', 10)
    self.pub.publish('hello')
    ```

    ## Use instead
    ```python
    self.pub = self.create_publisher(String, 'chatter', 10)
    self.pub.publish(String(data='hello'))
    ```
    """
    yield from _feedback_hits(package)
    for module, tree, index in installed_trees(package):
        if not any(i.top_level == "rclpy" for i in module.imports) or \
                index.defines_function("create_publisher"):
            continue
        known = known_messages(package, index)
        make = _publisher_maker(known, index)
        publishers = [*local_instances(tree, index, make),
                      *attribute_instances(tree, index, make)]
        messages = message_instances(package, tree, index, known) if publishers else []
        for publisher in publishers:
            for ref in publisher.refs:
                extra = _second(ref, index) if publisher.message.sends == "message" else None
                empty = _publish_call(ref, index) if publisher.message.sends == "message" \
                    else None
                if empty is not None and not empty.args and not empty.keywords:
                    yield Hit(Span(module.path, empty.lineno, empty.col_offset + 1),
                              f"`{ast.unparse(empty)}` is given no message: rclpy raises "
                              "TypeError (missing 1 required positional argument: 'msg')",
                              "Publish a message: `self.pub.publish(msg)`")
                foreign = next((k for k in empty.keywords if k.arg not in _SENT), None) \
                    if empty is not None else None
                if foreign is not None:
                    yield Hit(Span(module.path, foreign.lineno, foreign.col_offset + 1),
                              f"`{ast.unparse(ref)}.publish()` is given `{foreign.arg}=`: it "
                              "takes the message alone (`msg`), not its fields as keywords, and"
                              f" rclpy raises TypeError (unexpected keyword argument "
                              f"'{foreign.arg}')",
                              _fields_fix(ref, empty, publisher.message.message))
                if extra is not None:
                    yield Hit(Span(module.path, extra.lineno, extra.col_offset + 1),
                              f"`{ast.unparse(ref)}.publish()` is given more than the message:"
                              " it takes the message alone, rclpy raises TypeError",
                              "Publish the message alone: `self.pub.publish(msg)`")
                sent = _published(ref, index, publisher.message.methods)
                value = sent[1] if sent else None
                made = known(value.func) if isinstance(value, ast.Call) else None
                why = _not_a_message(value, publisher.message, messages,
                                     certain_type(value, package, tree, index), made) \
                    if value else None
                if sent is not None and value is not None and why:
                    yield _sent_hit(module.path, ref, sent[0], value, why, publisher.message)


def _fields_fix(ref: ast.expr, call: ast.Call, message: Message | None) -> str:
    """Publishing a message built from the fields a ``publish()`` call was given."""
    fields = ", ".join(f"{k.arg}=..." for k in call.keywords)
    made = f"{message.name.rpartition('/')[2]}({fields})" if message is not None \
        else f"<Message>({fields})"
    return f"Build the message and publish it: `{ast.unparse(ref)}.publish({made})`"


def _sent_hit(path: str, ref: ast.expr, method: str, value: ast.expr, why: str,
              sender: Publisher) -> Hit:
    what = sender.sends
    return Hit(Span(path, value.lineno, value.col_offset + 1),
               f"`{ast.unparse(ref)}.{method}()` is given `{ast.unparse(value)}`, {why}: rclpy "
               f"raises TypeError (it sends {what}s of the {_SENDER[what]}'s type only)",
               _FIXES[what])


_SENT_CLASS = lazy_pattern(r"\w+\.(?:msg\.\w+|action\.\w+\.\w+)")
"""A message class, or a class of an action's (``pkg.action.Fibonacci.Result``)."""


def _not_feedback(made: str | None) -> str | None:
    """Why an instance of ``made`` (a :data:`_SENT_CLASS`) is no action feedback, if it is."""
    if made is None or made.endswith("Feedback"):  # `Fibonacci_Feedback` of `_fibonacci` too
        return None
    shown = ".".join(made.split(".")[2:])
    return f"a `{shown}`, not the action's `Feedback`"


def _feedback_hits(package: Package) -> Iterator[Hit]:
    """The feedback an action server's execute callback publishes through its goal handle
    that is certainly no feedback message."""
    trees = {module.path: tree for module, tree, _ in installed_trees(package)}
    for path, _, function, handle, index in execute_callbacks(package):
        for ref in ast.walk(function):
            sent = _published(ref, index, _GOAL_HANDLE.methods) \
                if isinstance(ref, ast.Name) and ref.id == handle else None
            if sent is None:
                continue
            value = sent[1]
            why = _not_a_message(value, _GOAL_HANDLE, [],
                                 certain_type(value, package, trees[path], index)) or \
                _not_feedback(made_class(value, package, trees[path], index, _SENT_CLASS))
            if why:
                yield _sent_hit(path, ref, sent[0], value, why, _GOAL_HANDLE)
