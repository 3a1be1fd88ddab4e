"""PYC033: a node's create_* or get_parameter method given more positional arguments than it
takes."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import node_api_calls, node_subclasses
from pkgtool.rules.python._value_types import receiver_class
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import installed_trees

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
_FUNCTIONS = {"rclpy.spin_once": (("node",), ("executor", "timeout_sec")),
              "rclpy.init": _INIT, "rclpy.utilities.init": _INIT}
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
    keyword-only, and `rclpy.init(args)`: `init` takes keywords only (`args=args`). Calls
    passing `*args` are not judged, nor packages defining a function of the same name.

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
    nodes_of: dict[int, list[ast.ClassDef]] = {}
    for module, call, method, index in node_api_calls(package, POSITIONAL):
        positional, keywords = POSITIONAL[method]
        if any(isinstance(a, ast.Starred) for a in call.args) or \
                len(call.args) <= len(positional):
            continue
        nodes = nodes_of.setdefault(id(index), node_subclasses(index))
        if receiver_class(call.func.value, index) not in nodes:  # type: ignore[attr-defined]
            continue  # not `self.<method>(...)` in a method of a Node subclass
        extra = call.args[len(positional)]
        yield Hit(Span(module.path, extra.lineno, extra.col_offset + 1),
                  _message(method, positional, keywords, len(call.args)),
                  None if keywords else _DEFAULT)
    yield from _function_calls(package)
