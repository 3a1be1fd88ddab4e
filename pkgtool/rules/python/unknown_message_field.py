"""PYC019: a message constructed or used with a field its class does not have."""

from __future__ import annotations

import ast
from collections.abc import Iterator
from difflib import get_close_matches

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rosdistro import typo_of
from pkgtool.knowledge.message_fields import Message, close_field, constructor_options
from pkgtool.knowledge.tables import DEFAULT_DISTRO
from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.model.static_branches import depends_on_ros_distro
from pkgtool.rules.python._attribute_guards import guarded, probed_names
from pkgtool.rules.python._derived_messages import derived_instances
from pkgtool.rules.python._message_instances import (Instance, Known, fields_taken,
                                                     known_messages)
from pkgtool.rules.python._messages import message_instances
from pkgtool.rules.syntax_trees import Index, installed_trees
from pkgtool.rules.registry import rule


def _problem(message: Message, name: str) -> str:
    """```pkg/msg/Name` has no field `name``` with a near miss or the fields there are."""
    close = close_field(message, name)
    fields = ", ".join(f"`{f}`" for f in message.fields)
    hint = f"did you mean `{close}`?" if close else f"its fields: {fields}" if fields else (
        "it has no fields")
    return f"`{message.name}` has no field `{name}` ({hint})"


def _silent_lines(tree: ast.Module) -> list[tuple[int, int]]:
    """Line ranges never checked: both branches of a test on the ROS distribution (written
    for some only; code that never runs, ``if ROS_VERSION == 1:``, no PYC rule judges)."""
    return [(node.lineno, node.end_lineno or node.lineno)
            for node in nodes_of_class(tree, ast.If)
            if isinstance(node, ast.If) and depends_on_ros_distro(node.test)]


def _wrong_attributes(instance: Instance, index: Index, probed: frozenset[str]
                      ) -> Iterator[tuple[ast.Attribute, Message]]:
    """Attributes taken on the instance, or on its message-typed fields, that the message
    there does not have."""
    for node, message, _ in fields_taken(instance, index):
        if not message.has(node.attr) and not guarded(node, index, probed):
            yield node, message


@rule("PYC019", "unknown-message-field", Severity.ERROR,
      fix="Use a field the message has (see `ros2 interface show <type>`)")
def unknown_message_field(package: Package) -> Iterator[Hit]:
    """A message is given, set or read a field its class does not have.

    ## What it does
    Reports keyword arguments of a message constructor that are not fields of the message
    (`String(date='hi')`), positional arguments of a message constructor (`String('hi')`),
    and attributes read or set on a message instance that its class does not have
    (`msg.dat = 'hi'`, `twist.linear.xx = 1.0`, `msg.header.stamp.secs`), with the field
    meant when one is spelled alike; also attributes read on an interface class that it does
    not have: a service's or action's class has only `Request`/`Response`/`Event` or
    `Goal`/`Result`/`Feedback`/`Impl` (`Trigger.request()`), a message class its fields
    and constants (`GoalStatus.STATUS_SUCCEDED`). Checked are the messages, service requests and
    responses and action goals, results and feedbacks of pkgtool's table of the Jazzy
    interface packages installable as wheels (`std_msgs`, `geometry_msgs`, `sensor_msgs`,
    `nav_msgs`, `std_srvs`, ...), imported by name (an import is the only binding of the name
    in the module): all of them for a jazzy target; for a humble target those whose definition
    is the same on humble's branch of the ROS repositories (most of them: not
    `sensor_msgs/Range`, which gained `variance` in Jazzy, nor the messages rosidl derives,
    such as service events); for kilted (not compared) and rolling (whose definitions change)
    none. Positional arguments are reported for any message class of the table on every target
    (every generated message class takes keyword arguments only), with the fields to name when
    the target's definition is known. On humble, `check_fields=` is reported too (constructors
    take it since Iron). An instance is certain only as a local variable bound once in its
    function (or module) by `msg = Type()`, never otherwise (no parameter, no second
    assignment, no `global`), or as `self.x` in a class whose methods all assign
    `self.x = Type()` (or `None`, a placeholder, or the message a callback gets: `self.last =
    msg`) when nothing else in the module stores an attribute `x` and no `setattr` could, or
    as a parameter of a callback the module registers with known types that agree: the
    message of `create_subscription` (not `raw=True`), the request and response of
    `create_service`, the goal of an `ActionServer` (`goal_handle.request`), when the callback
    is a plain method of the registering class (`self.on_message`) or a plain function bound
    once in the module and never rebinds the parameter, or as a parameter annotated with a
    known message class (`def describe(msg: JointState)`, `Optional[Twist]`; not a method's
    receiver, not a string annotation) that its function never rebinds, or as a service's
    response:
    `future.result()` (used directly, or assigned as above) of a future that is certainly a
    client's `call_async()` (or the future a done callback registered on one gets) of a client
    certainly made by `create_client()` for a known service; fields of fields are followed while
    their message class is certain (not after `msg.pose = ...`), also through a name bound once
    to a field (`header = msg.header`) or to an element of a field holding messages (`last =
    msg.poses[-1]`), through a `for` or comprehension target over such a field (`for pose in
    msg.poses`, with `enumerate()` too) and an element used where it is indexed
    (`msg.poses[0].pose`). Names starting with `_`,
    constants (`GoalStatus.STATUS_SUCCEEDED`), code inside `try` blocks that catch
    `AttributeError`, names the module passes to `hasattr` and annotations Python never
    evaluates (`request: Fibonacci.Request = goal_handle.request` in a function) are never
    reported.
    The messages, services and actions a package of the workspace defines in its own `.msg`,
    `.srv` and `.action` files (`tutorial_interfaces/msg/Num.msg` beside the linted package)
    are checked the same way, on every target, with the fields those files declare; `.idl`
    files, and interfaces two files define, are not read.

    ## Why is this bad?
    Message classes have `__slots__`: setting or reading a field that does not exist raises
    `AttributeError`, often inside a callback where it only shows up as a log line. A
    keyword argument that is not a field is ignored since Iron (the value is silently lost;
    with `ROS_PYTHON_CHECK_FIELDS=1`, and always on Humble, the constructor raises
    `AssertionError: Invalid arguments passed to constructor`). Message constructors take
    keyword arguments only: `String('hi')` raises `TypeError`.

    ## Example
    ```python
    msg = String()
    msg.dat = 'hello'
    cmd = Twist(linear=Vector3(xx=0.5))
    hello = String('hi')
    ```

    ## Use instead
    ```python
    msg = String()
    msg.data = 'hello'
    cmd = Twist(linear=Vector3(x=0.5))
    hello = String(data='hi')
    ```
    """
    distro = package.context.distro
    ignored = ("raises AssertionError" if distro == "humble" else
               "ignores the argument (raises AssertionError where ROS_PYTHON_CHECK_FIELDS=1)")
    for module, tree, index in installed_trees(package):
        known = known_messages(package, index)
        probed, silent = probed_names(index), _silent_lines(tree)
        for argument, call, name in _positional(index, known_messages(package, index,
                                                                      DEFAULT_DISTRO)):
            if not _within(argument, silent):
                yield Hit(Span(module.path, argument.lineno, argument.col_offset + 1),
                          f"`{ast.unparse(call.func)}` is given the positional argument "
                          f"`{ast.unparse(argument)}`: `{name}` takes fields as keywords "
                          "only, the constructor raises TypeError", _keyword_fix(known, call))
        for keyword, call, message in _wrong_keywords(index, known, constructor_options(distro)):
            if not _within(keyword, silent):
                yield Hit(Span(module.path, keyword.lineno, keyword.col_offset + 1),
                          f"{_problem(message, str(keyword.arg))}: `{ast.unparse(call.func)}` "
                          f"{ignored}", _fix(message, str(keyword.arg)))
        for node, owner, meant in _wrong_class_attributes(index, known, probed):
            if not _within(node, silent):
                yield Hit(Span(module.path, node.end_lineno or node.lineno,
                               (node.end_col_offset or 0) - len(node.attr) + 1),
                          f"{owner} has no attribute `{node.attr}`{meant}: reading "
                          f"`{ast.unparse(node)}` raises AttributeError")
        places: dict[tuple[str, str], list[tuple[ast.Attribute, Message]]] = {}
        held = message_instances(package, tree, index, known)
        seen: set[int] = set()
        for instance in (*held, *derived_instances(held, tree, index)):
            for node, message in _wrong_attributes(instance, index, probed):
                if not _within(node, silent) and id(node) not in seen:
                    seen.add(id(node))
                    places.setdefault((message.name, node.attr), []).append((node, message))
        for found in places.values():
            yield _field_hit(module.path, sorted(found, key=lambda f: _where(f[0])))


def _where(node: ast.Attribute) -> tuple[int, int]:
    """Where the attribute's name is (1-based line and column)."""
    return node.end_lineno or node.lineno, (node.end_col_offset or 0) - len(node.attr) + 1


def _field_hit(path: str, found: list[tuple[ast.Attribute, Message]]) -> Hit:
    """One hit for every use of one wrong field of one message in a module (one mistake):
    the first use, the others related."""
    node, message = found[0]
    doing = "reading" if isinstance(node.ctx, ast.Load) else "setting"
    others = sorted({_where(n)[0] for n, _ in found[1:]} - {_where(node)[0]})
    also = f" (also on line{'s' if len(others) > 1 else ''} " \
        f"{', '.join(map(str, others))})" if others else ""
    return Hit(Span(path, *_where(node)),
               f"{_problem(message, node.attr)}: {doing} `{ast.unparse(node)}` raises "
               f"AttributeError{also}", _fix(message, node.attr),
               related=tuple(Span(path, *_where(n)) for n, _ in found[1:]))


_COMPANIONS = {"srv": ("Request", "Response", "Event"),
               "action": ("Goal", "Result", "Feedback", "Impl")}
"""The public attributes of a service and of an action class."""


def _wrong_class_attributes(index: Index, known: Known, probed: frozenset[str]
                            ) -> Iterator[tuple[ast.Attribute, str, str]]:
    """Attributes read on a known interface class that it does not have (a service's
    ``Trigger.request``, a message constant misspelt), with the class and a near miss; not in
    annotations Python never evaluates (``request: Fibonacci.Request = ...`` in a function)."""
    for node in index.attributes:
        dotted = index.qualified(node.value)
        if dotted is None or node.attr.startswith("_"):  # not a known class: no import names it
            continue
        kind = dotted.split(".")
        companions = _COMPANIONS.get(kind[1], ()) if len(kind) == 3 else ()
        if companions and known(ast.Attribute(value=node.value, attr=companions[0],
                                              ctx=ast.Load())):
            if node.attr not in companions and not guarded(node, index, probed) and \
                    not index.in_unevaluated_annotation(node):
                close = get_close_matches(node.attr, companions, n=1) or [
                    c for c in companions if c.lower() == node.attr.lower()]
                yield node, f"`{'/'.join(kind)}`", _meant(close)
            continue
        message = known(node.value) if not companions else None
        if message is not None and not message.has(node.attr) \
                and not guarded(node, index, probed) and not index.in_unevaluated_annotation(node):
            names = sorted([*message.constants, *message.fields])
            yield node, f"`{message.name}`", _meant(get_close_matches(node.attr, names, n=1))


def _meant(close: list[str]) -> str:
    return f" (did you mean `{close[0]}`?)" if close else ""


def _wrong_keywords(index: Index, known: Known, options: frozenset[str]
                    ) -> Iterator[tuple[ast.keyword, ast.Call, Message]]:
    """Keyword arguments of known message constructors that name no field nor one of the
    constructor's ``options``."""
    for call in index.calls:
        message = known(call.func)
        for keyword in call.keywords if message is not None else ():
            if keyword.arg and keyword.arg not in message.fields and keyword.arg not in options:
                yield keyword, call, message


def _positional(index: Index, known: Known) -> Iterator[tuple[ast.expr, ast.Call, str]]:
    """The first positional argument of each constructor of a message class ``known`` knows
    given some (generated message classes take keyword arguments only, on every
    distribution), with the class's name; calls unpacking ``*args`` are left alone."""
    for call in index.calls:
        if call.args and not any(isinstance(a, ast.Starred) for a in call.args) and (
                message := known(call.func)) is not None:
            yield call.args[0], call, message.name


def _keyword_fix(known: Known, call: ast.Call) -> str | None:
    """Name the fields the positional arguments would fill in order (``String(data=...)``),
    when the target's definition of the message is known."""
    message = known(call.func)
    names = list(message.fields)[:len(call.args)] if message is not None else []
    named = ", ".join(f"{name}=..." for name in names)
    return f"Name the fields: `{ast.unparse(call.func)}({named})`" if names else None


def _within(node: ast.AST, ranges: list[tuple[int, int]]) -> bool:
    """True when ``node`` starts on a line of one of ``ranges``."""
    line = getattr(node, "lineno", 0)
    return any(first <= line <= last for first, last in ranges)


def _fix(message: Message, name: str) -> str | None:
    """``Write `x``` when the near miss the message names is a typo away (what the fixer
    renames); a field spelled only somewhat alike is named in the message alone."""
    close = close_field(message, name)
    return f"Write `{close}`" if close and typo_of(name, [close]) else None
