"""PYC031: the Parameter object ``get_parameter()`` returns used where its value is meant."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import argument
from pkgtool.rules.python._value_types import PARAMETER, certain_type, parameter_read
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, installed_trees

_VALUES = {
    "create_timer": (("timer_period_sec",), ("timer_period_sec",)),
    "create_publisher": (("msg_type", "topic", "qos_profile"), ("topic", "qos_profile")),
    "create_subscription": (("msg_type", "topic", "callback", "qos_profile"),
                            ("topic", "qos_profile")),
    "create_service": (("srv_type", "srv_name"), ("srv_name",)),
    "create_client": (("srv_type", "srv_name"), ("srv_name",)),
}
"""rclpy Node methods (Jazzy): their leading positional parameters, and those that take a
plain value (a number or a string) that a ``Parameter`` object is not."""
_CONVERSIONS = frozenset({"float", "int"})
_VALUE_COMPARISONS = (ast.Eq, ast.NotEq, ast.Lt, ast.LtE, ast.Gt, ast.GtE)
"""Comparisons of values (not `is`, `in`)."""
_ARITHMETIC = "is used in arithmetic, which raises TypeError"


def _uses(tree: ast.Module, index: Index) -> Iterator[tuple[ast.expr, str]]:
    """Expressions used as plain values, and how each is used and what that does."""
    for call in index.calls:
        method = call.func.attr if isinstance(call.func, ast.Attribute) else ""
        if method in _VALUES:
            positional, values = _VALUES[method]
            for name in values:
                given = argument(call, positional, name)
                if given is not None:
                    yield given, f"is given as `{name}` to `{method}()`: rclpy raises TypeError"
        elif isinstance(call.func, ast.Name) and call.func.id in _CONVERSIONS and \
                len(call.args) == 1 and index.qualified(call.func) in (None, call.func.id):
            yield call.args[0], f"is given to `{call.func.id}()`, which raises TypeError"
    for node in nodes_of_class(tree, ast.BinOp, ast.Compare):
        if isinstance(node, ast.BinOp):
            yield node.left, _ARITHMETIC
            if not isinstance(node.op, ast.Mod):  # `'%s' % parameter` formats the object
                yield node.right, _ARITHMETIC
        elif isinstance(node, ast.Compare) and all(isinstance(o, _VALUE_COMPARISONS)
                                                   for o in node.ops):
            for operand in (node.left, *node.comparators):
                yield operand, ("is compared: `==` with a value is always false, `<` raises "
                                "TypeError")


def _holders(tree: ast.Module) -> set[str]:
    """The names and attribute names an assignment of the module gives a ``get_parameter()``
    call (only they, and the calls themselves, can be a ``Parameter``)."""
    found: set[str] = set()
    for statement in nodes_of_class(tree, ast.Assign, ast.AnnAssign):
        if isinstance(statement, (ast.Assign, ast.AnnAssign)) and parameter_read(statement.value):
            targets = statement.targets if isinstance(statement, ast.Assign) else \
                [statement.target]
            found.update(t.id if isinstance(t, ast.Name) else t.attr for t in targets
                         if isinstance(t, (ast.Name, ast.Attribute)))
    return found


def _candidate(value: ast.expr, holders: set[str]) -> bool:
    return parameter_read(value) or isinstance(value, ast.Name) and value.id in holders or \
        isinstance(value, ast.Attribute) and value.attr in holders


@rule("PYC031", "parameter-object-as-value", Severity.ERROR,
      fix="Take the parameter's value: `self.get_parameter('period').value`")
def parameter_object_as_value(package: Package) -> Iterator[Hit]:
    """The `Parameter` object `get_parameter()` returns is used where its value is meant.

    ## What it does
    In the methods of classes deriving from rclpy's `Node` (installed modules importing
    rclpy and defining no `get_parameter` of their own), finds `self.get_parameter('x')`
    without `.value`, directly or through a local name or a `self.x` attribute every
    assignment of which is such a call, and reports it where a plain value is needed: the
    period of `create_timer`, the topic or QoS depth of `create_publisher` and
    `create_subscription`, the name of `create_service` and `create_client`, `float()` or
    `int()`, arithmetic (`period * 2`) and comparisons (`speed > 1.0`).

    ## Why is this bad?
    `get_parameter()` returns an `rclpy.parameter.Parameter`, not its value: `create_timer`
    and `float()` raise `TypeError`, so do arithmetic and ordering; a topic name raises in
    rclpy's name validation, and `==` is silently always false. The node dies at start-up,
    or behaves as if the parameter had another value.

    ## Example
    ```python
    self.declare_parameter('period', 0.5)
    period = self.get_parameter('period')
    self.timer = self.create_timer(period, self.tick)
    ```

    ## Use instead
    ```python
    self.declare_parameter('period', 0.5)
    period = self.get_parameter('period').value
    self.timer = self.create_timer(period, self.tick)
    ```
    """
    for module, tree, index in installed_trees(package):
        if not any(i.top_level == "rclpy" for i in module.imports) or \
                not any(parameter_read(call) for call in index.calls):
            continue
        holders = _holders(tree)
        for value, how in _uses(tree, index):
            if _candidate(value, holders) and \
                    certain_type(value, package, tree, index) == PARAMETER:
                yield Hit(Span(module.path, value.lineno, value.col_offset + 1),
                          f"`{ast.unparse(value)}` is the `Parameter` object "
                          f"`get_parameter()` returns, not its value, and {how}")
