"""PYC033: a node's create_* or get_parameter method given more positional arguments than it
takes."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import node_api_calls, node_subclasses
from pkgtool.rules.python._assignments import assigned_values
from pkgtool.rules.python._value_types import receiver_class
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import installed_trees
from pkgtool.lazy_regex import lazy_pattern

POSITIONAL = {
    "create_publisher": (("msg_type", "topic", "qos_profile"),
                         ("callback_group", "event_callbacks", "qos_overriding_options",
                          "publisher_class")),
    "create_subscription": (("msg_type", "topic", "callback", "qos_profile"),
                            ("callback_group", "event_callbacks", "qos_overriding_options",
                             "raw")),
    "create_service": (("srv_type", "srv_name", "callback"), ("qos_profile", "callback_group")),
    "create_client": (("srv_type", "srv_name"), ("qos_profile", "callback_group")),
    "get_parameter": (("name",), ()),
}
"""rclpy ``Node`` methods (Humble to Rolling) whose later parameters are keyword-only: the
positional ones, then the keyword-only ones (``get_parameter`` takes the name alone)."""
_DEFAULT = "Give the default where the parameter is declared, `self.declare_parameter('x', 0.5)`"
_INIT = ((), ("args", "context", "domain_id", "signal_handler_options"))
_SHUTDOWN = ((), ("context", "uninstall_handlers"))
_FUNCTIONS = {"rclpy.spin_once": (("node",), ("executor", "timeout_sec")),
              "rclpy.init": _INIT, "rclpy.utilities.init": _INIT,
              "rclpy.shutdown": _SHUTDOWN, "rclpy.try_shutdown": ((), ("context",)),
              "rclpy.utilities.shutdown": ((), ("context",)),
              "rclpy.utilities.try_shutdown": ((), ("context",))}
"""rclpy functions (Humble to Rolling) whose later parameters are keyword-only, the same way."""


def _message(method: str, positional: tuple[str, ...], keywords: tuple[str, ...],
             count: int) -> str:
    given = ", ".join(f"`{p}`" for p in positional)
    named = ", ".join(f"`{k}=`" for k in keywords)
    rest = f" (the others are keyword-only: {named})" if keywords else ""
    if not positional:
        return f"`{method}()` takes keyword arguments only ({named}) but is given {count} " \
            "by position: rclpy raises TypeError"
    return f"`{method}()` takes {len(positional)} positional argument" \
        f"{'s' if len(positional) > 1 else ''} ({given}) but is given {count}: rclpy raises " \
        f"TypeError{rest}"


def _function_calls(package: Package) -> Iterator[Hit]:
    """Calls of :data:`_FUNCTIONS` given more positional arguments than they take."""
    for module, _, index in installed_trees(package):
        for call in index.calls:
            known = _FUNCTIONS.get(index.qualified(call.func) or "")
            if known is None or any(isinstance(a, ast.Starred) for a in call.args) or \
                    len(call.args) <= len(known[0]):
                continue
            extra = call.args[len(known[0])]
            meant = known[1][0] if not known[0] else known[1][-1]
            yield Hit(Span(module.path, extra.lineno, extra.col_offset + 1),
                      _message(ast.unparse(call.func), *known, len(call.args)),
                      f"Pass it by keyword: `{meant}=...`")


_EXECUTOR_SLOTS = {"rclpy.spin_until_future_complete": 2}
"""rclpy functions taking an executor by position, and its index (``node, future, executor,
timeout_sec``)."""
_TIMEOUT_NAME = lazy_pattern(r"(?i)time|sec|duration|wait")


def _timeouts_as_executor(package: Package) -> Iterator[Hit]:
    """A number, or a name telling a time, given in the executor's place of
    :data:`_EXECUTOR_SLOTS`."""
    for module, _, index in installed_trees(package):
        for call in index.calls:
            slot = _EXECUTOR_SLOTS.get(index.qualified(call.func) or "")
            if slot is None or len(call.args) <= slot or \
                    any(isinstance(a, ast.Starred) for a in call.args[:slot + 1]):
                continue
            value = call.args[slot]
            if _is_number(value) or _TIMEOUT_NAME.search(_last_name(value)):
                yield Hit(Span(module.path, value.lineno, value.col_offset + 1),
                          f"`{ast.unparse(value)}` is given in the place of `"
                          f"{ast.unparse(call.func)}()`'s `executor` (its third parameter; the "
                          "timeout is the fourth): the call fails with AttributeError",
                          f"Pass it by keyword: `timeout_sec={ast.unparse(value)}`")


def _is_number(value: ast.expr) -> bool:
    """True for a number, written or computed from numbers (``2.0``, ``-1``, ``1 / 2``)."""
    if isinstance(value, ast.UnaryOp):
        return _is_number(value.operand)
    if isinstance(value, ast.BinOp):
        return _is_number(value.left) and _is_number(value.right)
    return isinstance(value, ast.Constant) and type(value.value) in (int, float)


def _last_name(value: ast.expr) -> str:
    """The last identifier of a name or attribute (``args.timeout``: ``timeout``), else ''."""
    return value.id if isinstance(value, ast.Name) else \
        value.attr if isinstance(value, ast.Attribute) else ""


EXECUTORS = frozenset(f"rclpy.executors.{name}" for name in (
    "Executor", "SingleThreadedExecutor", "MultiThreadedExecutor", "EventsExecutor"))
"""rclpy's executor classes."""
_EXECUTOR_METHODS = {"spin": (), "spin_once": ("timeout_sec",),
                     "spin_until_future_complete": ("future", "timeout_sec"),
                     "add_node": ("node",), "remove_node": ("node",),
                     "shutdown": ("timeout_sec",)}
"""Executor methods (Humble to Rolling) and their parameters."""


def _executor_calls(package: Package) -> Iterator[Hit]:
    """Calls of an executor's methods (on a local name or ``self.x`` every assignment of which
    makes one of rclpy's executors) given more positional arguments than they take."""
    for module, tree, index in installed_trees(package):
        for call in index.calls:
            func = call.func
            taken = _EXECUTOR_METHODS.get(func.attr) if isinstance(func, ast.Attribute) \
                else None
            if taken is None or len(call.args) <= len(taken) or \
                    any(isinstance(a, ast.Starred) for a in call.args):
                continue
            values = assigned_values(func.value, package, tree, index)  # type: ignore
            if not values or not all(isinstance(v, ast.Call) and
                                     i.qualified(v.func) in EXECUTORS for v, i in values):
                continue
            extra, spin = call.args[len(taken)], func.attr == "spin"  # type: ignore
            hint = " (give the executor its node with `add_node(node)`)" if spin else ""
            yield Hit(Span(module.path, extra.lineno, extra.col_offset + 1),
                      f"`{ast.unparse(func)}()` takes {len(taken) or 'no'} argument"
                      f"{'s' if len(taken) != 1 else ''} but is given {len(call.args)}: "
                      f"Python raises TypeError{hint}",
                      "Add the node with `add_node()`, then call `spin()` alone" if spin
                      else "Pass only what the method takes")


@rule("PYC033", "too-many-rclpy-arguments", Severity.ERROR,
      fix="Pass the later arguments by keyword: `qos_profile=...`, `callback_group=...`")
def too_many_rclpy_arguments(package: Package) -> Iterator[Hit]:
    """A node's `create_*` or `get_parameter` method is given too many positional arguments.

    ## What it does
    Reports `self.create_publisher(...)`, `create_subscription`, `create_service`,
    `create_client` and `get_parameter` calls in the methods of a `Node` subclass that pass
    more positional arguments than the method's positional parameters: `create_client` takes
    two (`srv_type`, `srv_name`), `create_service` three, `create_publisher` three,
    `create_subscription` four; everything after them (`qos_profile` of a client or service,
    `callback_group`, ...) is keyword-only (Humble to Rolling). `get_parameter` takes the
    name alone: `self.get_parameter('period', 0.5)`, a default given as to `dict.get`, is
    the usual case. Also reports `rclpy.spin_once(node, 0.1)`: its `timeout_sec` is
    keyword-only, and `rclpy.init(args)`: `init` takes keywords only (`args=args`), as do
    `rclpy.shutdown` and `rclpy.try_shutdown` (`context=`: `rclpy.shutdown(callback)` does
    not register a callback), and an
    executor's `spin(node)` (it takes no argument: `add_node(node)` gives it the node; also
    `spin_once`, `add_node` and the others given too many), and a timeout given to
    `rclpy.spin_until_future_complete(node, future, 5.0)` in the place of its third
    parameter, `executor` (a number, or a name telling a time: `args.timeout`, `wait_sec`),
    which fails with AttributeError. Calls passing `*args` are not
    judged, nor packages defining a function of the same name.

    ## Why is this bad?
    Python raises `TypeError: create_client() takes 3 positional arguments but 4 were given`
    when the line runs, usually in the node's constructor: the node never starts.

    ## Example
    ```python
    self.client = self.create_client(AddTwoInts, 'add', self.group)
    ```

    ## Use instead
    ```python
    self.client = self.create_client(AddTwoInts, 'add', callback_group=self.group)
    ```
    """
    for module, call, method, index in node_api_calls(package, POSITIONAL):
        positional, keywords = POSITIONAL[method]
        if any(isinstance(a, ast.Starred) for a in call.args) or \
                len(call.args) <= len(positional):
            continue
        receiver = receiver_class(call.func.value, index)  # type: ignore[attr-defined]
        if receiver not in node_subclasses(index):
            continue  # not `self.<method>(...)` in a method of a Node subclass
        extra = call.args[len(positional)]
        yield Hit(Span(module.path, extra.lineno, extra.col_offset + 1),
                  _message(method, positional, keywords, len(call.args)),
                  None if keywords else _DEFAULT)
    yield from _function_calls(package)
    yield from _executor_calls(package)
    yield from _timeouts_as_executor(package)
