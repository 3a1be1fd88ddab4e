"""PYC016: an rclpy logger called like ``print`` or Python's ``logging``."""

from __future__ import annotations

import ast
import difflib
from collections.abc import Callable, Iterator
from functools import cache

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.ast_nodes import descendants
from pkgtool.model.span import Span
from pkgtool.rules.node_api import node_subclasses, unpacks
from pkgtool.rules.python._field_reads import field_reads
from pkgtool.rules.python._loggers import (GETTERS, LEVELS, MESSAGE, logged_message,
                                           logger_method_calls)
from pkgtool.rules.python._message_instances import known_messages
from pkgtool.rules.python._messages import message_instances
from pkgtool.rules.python._value_types import NUMBER_TYPES, certain_type
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import FUNCTIONS, Index, installed_trees

OPTIONS = frozenset({"name", "throttle_duration_sec", "throttle_time_source_type",
                     "skip_first", "once"})
"""The keyword arguments rclpy's logger accepts (Jazzy)."""
ATTRIBUTES = LEVELS | {"log", "get_child", "set_level", "get_effective_level", "is_enabled_for",
                       "name", "contexts", "logger_sublogger_namepair"}
"""The attributes of rclpy's logger (``RcutilsLogger``) in Humble, Jazzy and Rolling."""


@cache
def python_logger() -> frozenset[str]:
    """The attributes of Python's ``logging.Logger``, which another ``get_logger()`` may give
    (importing ``logging`` costs a lint run ~5 ms: only a logger call that rclpy's logger does
    not have asks)."""
    import logging

    return frozenset(dir(logging.Logger)) | {"level", "parent", "propagate", "handlers",
                                             "disabled", "filters", "manager", "root"}


def _problem(call: ast.Call, typed: Callable[[ast.expr], str | None], level: str
             ) -> str | None:
    """What is wrong with the arguments of a logger method call, if anything (``typed``: the
    type an expression certainly has, if known). rclpy reads the options and the message
    only for a level that is enabled: ``debug()`` raises once DEBUG messages are."""
    raises = "rclpy raises `TypeError` once DEBUG messages are enabled" if level == "debug" \
        else "rclpy raises `TypeError`"
    if unpacks(call):
        return None
    if len(call.args) > 1:
        return "takes one message: rclpy raises `TypeError` for the other arguments; format " \
               "them into the message with an f-string"
    by_keyword = [k.value for k in call.keywords if k.arg == MESSAGE]
    if by_keyword and call.args:
        return "passes the message twice, by position and as `message=`: rclpy raises " \
               "`TypeError`"
    unknown = sorted(k.arg for k in call.keywords if k.arg and k.arg not in OPTIONS | {MESSAGE})
    if unknown:
        return f"has no option `{unknown[0]}`: {raises} (its options are " \
               "`throttle_duration_sec`, `skip_first`, `once`)"
    message = logged_message(call)
    if isinstance(message, ast.Constant) and not isinstance(message.value, str) or \
            isinstance(message, (ast.List, ast.Tuple, ast.Dict, ast.Set)):
        return f"takes a string: {raises} for anything else; write `str(...)` or an f-string"
    given = typed(message) if message is not None else None
    if given is not None:
        return f"is given {given}, not a string: {raises}; write `str(...)` or an f-string"
    return None


def _a(kind: str | None) -> str:
    return f"an {kind}" if kind == "int" else f"a {kind}"


def _typer(package: Package, tree: ast.Module, index: Index) -> Callable[[ast.expr], str | None]:
    """What an expression of the module certainly is, when that is no string: a message
    (``a `geometry_msgs/msg/Twist` message``), a number or a bool (a literal, a conversion, a
    local or node attribute bound only to one, a message field)."""
    known: dict[int, str] | None = None

    def typed(value: ast.expr) -> str | None:
        nonlocal known
        if known is None:
            known = {id(r): f"a `{instance.message.name}` message"
                     for instance in message_instances(package, tree, index,
                                                       known_messages(package, index))
                     for r in instance.refs}
            known.update({key: _a(read.python_type) for key, read in
                          field_reads(tree, index, package).items()
                          if read.python_type in NUMBER_TYPES})
        if id(value) in known:
            return known[id(value)]
        if _caught_exception(value, index):
            return f"the exception `{ast.unparse(value)}` it caught"
        found = certain_type(value, package, tree, index)
        return _a(found) if found in NUMBER_TYPES else None

    return typed


def _caught_exception(value: ast.expr, index: Index) -> bool:
    """True for ``e`` read in the body of the ``except ... as e:`` binding it, when nothing
    there rebinds ``e``."""
    if not isinstance(value, ast.Name):
        return False
    child, parent = value, index.parents.get(id(value))
    while parent is not None and not isinstance(parent, (*FUNCTIONS, ast.Lambda, ast.ClassDef)):
        if isinstance(parent, ast.ExceptHandler) and parent.name == value.id:
            return any(child is statement for statement in parent.body) and not any(
                isinstance(n, ast.Name) and n.id == value.id and not isinstance(n.ctx, ast.Load)
                for statement in parent.body for n in descendants(statement))
        child, parent = parent, index.parents.get(id(parent))
    return False


@rule("PYC016", "invalid-logger-call", Severity.ERROR,
      fix="Pass one string: `self.get_logger().info(f'Count: {count}')`")
def invalid_logger_call(package: Package) -> Iterator[Hit]:
    """An rclpy logger is called with several arguments, an unknown option, no string, or a
    method it does not have.

    ## What it does
    Checks calls of methods of rclpy loggers: `<node>.get_logger()`,
    `rclpy.logging.get_logger(...)`, and names or attributes (`self.logger`) that the module
    only ever assigns one of those. Calls of `debug`, `info`, `warning`, `warn`, `error` and
    `fatal` must pass one message (by position, or by keyword as `message=`) and only rclpy's
    options (`throttle_duration_sec`, `throttle_time_source_type`, `skip_first`, `once`,
    `name`); calls that unpack `*args` or `**kwargs` are not checked. The message must be a
    string: a literal number or container, a message, a number or bool a name certainly holds,
    or the exception an `except ... as e:` caught (`error(e)`, in its handler) is reported.
    A method rclpy's logger
    does not have (`err`, `infor`, and `exception` or `critical` of Python's `logging`) is
    reported too; Python's logger methods only on `self.get_logger()` in a `Node` subclass
    and `rclpy.logging.get_logger()`, as another class's `get_logger()` may give a Python
    logger. `self.get_logger()` in a class of the package with a `get_logger` method of its
    own, or deriving from one by name (a behaviour tree's nodes), is not rclpy's and is left
    alone.

    ## Why is this bad?
    rclpy's logger is neither `print` nor Python's `logging`: `info('count', n)` raises
    `TypeError: RcutilsLogger.info() takes 2 positional arguments but 3 were given`,
    `info('x %s', n)` too, `info(5)` raises "incompatible function arguments", and an option
    such as `end=` raises `TypeError: parameter "end" is not one of the recognized logging
    options`; `err('x')` or `exception('x')` raise `AttributeError`. The node dies in the
    callback that logs (for a wrong option or message given to `debug()`, once DEBUG messages
    are enabled: rclpy reads them only for a level it logs).

    ## Example
    ```python
    self.get_logger().info('Received', msg.data)
    ```

    ## Use instead
    ```python
    self.get_logger().info(f'Received {msg.data}')
    ```
    """
    for module, tree, index in installed_trees(package):
        if not any(i.top_level == "rclpy" for i in module.imports):
            continue
        typed = _typer(package, tree, index)
        for call, func in logger_method_calls(tree, index, package):
            problem = _problem(call, typed, func.attr) if func.attr in LEVELS else \
                _unknown_method(func, index) if func.attr not in ATTRIBUTES else None
            if problem:
                yield Hit(Span(module.path, call.lineno, call.col_offset + 1),
                          f"`{ast.unparse(func)}()` {problem}",
                          None if func.attr in LEVELS else _method_fix(func.attr))


def _unknown_method(func: ast.Attribute, index: Index) -> str | None:
    """Why calling ``func``, no method of rclpy's logger, fails; None when the logger may be
    Python's (a ``get_logger()`` of some other class) and has that method."""
    getter = func.value
    certain = isinstance(getter, ast.Call) and (
        index.qualified(getter.func) in GETTERS or
        isinstance(getter.func, ast.Attribute) and isinstance(getter.func.value, ast.Name) and
        getter.func.value.id == "self" and index.enclosing_class(getter) in
        node_subclasses(index))
    if func.attr in python_logger() and not certain:
        return None
    close = difflib.get_close_matches(func.attr, sorted(LEVELS), n=1, cutoff=0.6)
    also = f" (did you mean `{close[0]}`?)" if close else \
        f" (it logs with {', '.join(f'`{level}`' for level in sorted(LEVELS))})"
    return f"does not exist: rclpy's logger has no `{func.attr}` and raises " \
        f"`AttributeError`{also}"


def _method_fix(attr: str) -> str:
    meant = meant_level(attr)
    return f"Call `{meant}()`" if meant else "Call a logging method rclpy's logger has " \
        "(see the message)"


def meant_level(attr: str) -> str | None:
    """The one logging method of rclpy's logger that ``attr`` is a near miss of (``warn``
    and ``warning`` count as one: ``warning``), else None."""
    close = {"warning" if name == "warn" else name
             for name in difflib.get_close_matches(attr, sorted(LEVELS), n=len(LEVELS))}
    return close.pop() if len(close) == 1 else None
