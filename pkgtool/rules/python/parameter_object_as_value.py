"""PYC031: the Parameter object ``get_parameter()`` returns used where its value is meant."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import argument
from pkgtool.rules.python._format_specs import format_specs, percent_values
from pkgtool.rules.python._value_types import (PARAMETER, PARAMETER_TEXT, certain_type,
                                               parameter_read)
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
_NAMES = frozenset({"topic", "srv_name"})
"""Of those, the parameters taking a ROS name, which the text of a ``Parameter`` is not."""
_FRAMES = frozenset({"frame_id", "child_frame_id"})
"""Message fields holding a coordinate frame's name (``header.frame_id``)."""
_CONVERSIONS = frozenset({"float", "int"})
_VALUE_COMPARISONS = (ast.Eq, ast.NotEq, ast.Lt, ast.LtE, ast.Gt, ast.GtE)
"""Comparisons of values (not `is`, `in`)."""
_ARITHMETIC = "is used in arithmetic, which raises TypeError"


def _uses(tree: ast.Module, index: Index) -> Iterator[tuple[ast.expr, str, str | None]]:
    """Expressions used as plain values, how each is used and what that does, and what the
    text of a ``Parameter`` does there (None where it may be meant: a log line)."""
    for call in index.calls:
        method = call.func.attr if isinstance(call.func, ast.Attribute) else ""
        if method in _VALUES:
            positional, values = _VALUES[method]
            for name in values:
                given = argument(call, positional, name)
                if given is not None:
                    yield given, f"is given as `{name}` to `{method}()`: rclpy raises " \
                        "TypeError", f"is given as `{name}` to `{method}()`: rclpy rejects the " \
                        "name (no ROS name holds `<`, `.` or spaces)" if name in _NAMES else None
        elif isinstance(call.func, ast.Name) and call.func.id in _CONVERSIONS and \
                len(call.args) == 1 and index.qualified(call.func) in (None, call.func.id):
            yield call.args[0], f"is given to `{call.func.id}()`, which raises TypeError", None
    for value, spec, converted in format_specs(tree, index):
        if not converted:
            yield value, f"is formatted with `{spec}`: it has no format of its own, Python " \
                "raises TypeError", None
    for test in truth_tests(tree):
        yield test, "is tested for truth: a `Parameter` object is always true", None
    for node in nodes_of_class(tree, ast.BinOp, ast.Compare, ast.Assign):
        if isinstance(node, ast.BinOp):
            yield node.left, _ARITHMETIC, None
            if not isinstance(node.op, ast.Mod):  # `'%s' % parameter` formats the object
                yield node.right, _ARITHMETIC, None
            for value, conversion in percent_values(node):  # type: ignore[arg-type]
                if conversion["type"] not in "rsa":
                    yield value, f"is formatted with `{conversion.group(0)}`, a number's " \
                        "conversion: Python raises TypeError", None
        elif isinstance(node, ast.Compare) and all(isinstance(o, _VALUE_COMPARISONS)
                                                   for o in node.ops):
            for operand in (node.left, *node.comparators):
                yield operand, ("is compared: `==` with a value is always false, `<` raises "
                                "TypeError"), None
        elif isinstance(node, ast.Assign) and any(
                isinstance(t, ast.Attribute) and t.attr in _FRAMES for t in node.targets):
            yield node.value, "", "names a frame: the message names a frame that does not exist"


def truth_tests(tree: ast.Module) -> Iterator[ast.expr]:
    """The expressions Python tests for truth: the test of an ``if``, ``while``, conditional
    expression or ``assert``, the operand of ``not``, each operand of ``and``/``or`` there."""
    for node in nodes_of_class(tree, ast.If, ast.While, ast.IfExp, ast.Assert, ast.UnaryOp):
        test = node.operand if isinstance(node, ast.UnaryOp) else node.test  # type: ignore
        if isinstance(node, ast.UnaryOp) and not isinstance(node.op, ast.Not):
            continue
        yield from test.values if isinstance(test, ast.BoolOp) else (test,)


def _reads(value: ast.expr | None) -> bool:
    """True for a ``get_parameter()`` call, or ``str()`` or an f-string of one."""
    parts = value.args if isinstance(value, ast.Call) and isinstance(value.func, ast.Name) \
        and value.func.id == "str" else [v.value for v in value.values if isinstance(
            v, ast.FormattedValue)] if isinstance(value, ast.JoinedStr) else [value]
    return any(parameter_read(part) for part in parts)


def _holders(tree: ast.Module) -> set[str]:
    """The names and attribute names an assignment of the module gives a ``get_parameter()``
    call or its text (only they, and the calls themselves, can be a ``Parameter``)."""
    found: set[str] = set()
    for statement in nodes_of_class(tree, ast.Assign, ast.AnnAssign):
        if isinstance(statement, (ast.Assign, ast.AnnAssign)) and _reads(statement.value):
            targets = statement.targets if isinstance(statement, ast.Assign) else \
                [statement.target]
            found.update(t.id if isinstance(t, ast.Name) else t.attr for t in targets
                         if isinstance(t, (ast.Name, ast.Attribute)))
    return found


def _candidate(value: ast.expr, holders: set[str]) -> bool:
    return _reads(value) or isinstance(value, ast.Name) and value.id in holders or \
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
    `int()`, arithmetic (`period * 2`), comparisons (`speed > 1.0`), truth tests (`if
    self.get_parameter('calibrate'):`, always true) and formatting as a number
    (`f'{period:.2f}'`, `'%f' % period`). Also reports the
    text of such a call, `str(self.get_parameter('x'))` or an f-string formatting it
    (directly, or through a name or attribute every assignment of which is one), given as
    the topic or service name of those methods or assigned to a `frame_id` or
    `child_frame_id` field: it is `<rclpy.parameter.Parameter object at 0x...>`, not the
    value (the text of a parameter in a log line is left alone).

    ## Why is this bad?
    `get_parameter()` returns an `rclpy.parameter.Parameter`, not its value: `create_timer`
    and `float()` raise `TypeError`, so do arithmetic and ordering; a topic name raises in
    rclpy's name validation, and `==` is silently always false. The node dies at start-up,
    or behaves as if the parameter had another value. Its text makes rclpy reject the topic
    or service name, or sends messages in a frame no transform knows.

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
        for value, how, as_text in _uses(tree, index):
            found = certain_type(value, package, tree, index, texts=True) \
                if _candidate(value, holders) else None
            if found == PARAMETER and how:
                yield Hit(Span(module.path, value.lineno, value.col_offset + 1),
                          f"`{ast.unparse(value)}` is the `Parameter` object "
                          f"`get_parameter()` returns, not its value, and {how}")
            elif found == PARAMETER_TEXT and as_text:
                yield Hit(Span(module.path, value.lineno, value.col_offset + 1),
                          f"`{ast.unparse(value)}` is the text of the `Parameter` object "
                          "`get_parameter()` returns (`<rclpy.parameter.Parameter object at "
                          f"0x...>`), not its value, and {as_text}")
