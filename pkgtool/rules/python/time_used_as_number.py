"""PYC056: an rclpy ``Time`` or ``Duration`` computed, compared or formatted as a plain number."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._format_specs import format_specs, percent_values
from pkgtool.rules.python._rclpy_objects import DURATION, TIME, object_class
from pkgtool.rules.python._value_types import NUMBER_TYPES, certain_type
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, installed_trees

_SHORT = {TIME: "Time", DURATION: "Duration"}
_BUILTINS = frozenset({"float", "int", "round", "abs"})
_MATH = frozenset({"math.floor", "math.ceil", "math.isclose", "math.fabs", "math.sqrt"})
"""Builtins and ``math`` functions that take a real number (rclpy's classes are not)."""
_SECONDS = frozenset({"time.time", "time.monotonic", "time.perf_counter"})
"""Standard clocks that give a float of seconds."""
_OPERATORS = {ast.Add: "+", ast.Sub: "-", ast.Mult: "*", ast.Div: "/", ast.FloorDiv: "//",
              ast.Mod: "%", ast.Pow: "**"}
_ORDERING = (ast.Lt, ast.LtE, ast.Gt, ast.GtE)
_COMPARISONS = (*_ORDERING, ast.Eq, ast.NotEq)
_TEXT_CONVERSIONS = frozenset("sra")
"""``%`` conversions that take any object (its text)."""


class _Kinds:
    """What an operand is, for one module: an rclpy time class, a number, or neither."""

    def __init__(self, package: Package, tree: ast.Module, index: Index) -> None:
        self.package, self.tree, self.index = package, tree, index

    def time_class(self, value: ast.expr) -> str | None:
        """``Time`` or ``Duration`` (rclpy's) when ``value`` certainly is one."""
        if not isinstance(value, (ast.Call, ast.Name, ast.Attribute, ast.BinOp)):
            return None
        return _SHORT.get(object_class(value, self.package, self.tree, self.index) or "")

    def number(self, value: ast.expr) -> bool:
        """True when ``value`` certainly is an int, float or bool."""
        if isinstance(value, ast.Call) and isinstance(value.func, ast.Attribute) and \
                self.index.qualified(value.func) in _SECONDS:
            return True
        return certain_type(value, self.package, self.tree, self.index) in NUMBER_TYPES


def _arithmetic(node: ast.BinOp, kinds: _Kinds) -> str | None:
    """Why ``node`` fails on every distribution, or None: a time class with a number
    (``Duration * number`` aside: Rolling scales durations), or two ``Time`` added."""
    symbol = _OPERATORS.get(type(node.op))
    if symbol is None:
        return None
    left = kinds.time_class(node.left)
    right = kinds.time_class(node.right)
    if left == right == "Time" and symbol == "+":
        return "adds two rclpy `Time`s (a `Time` plus a `Duration` is what rclpy adds)"
    if (left is None) == (right is None):
        return None
    cls = left or right
    if not kinds.number(node.right if left else node.left) or \
            (left == "Duration" and symbol == "*"):
        return None
    return f"mixes an rclpy `{cls}` with a plain number in `{symbol}`"


def _comparison(left: ast.expr, op: ast.cmpop, right: ast.expr, kinds: _Kinds) -> str | None:
    """Why comparing ``left`` with ``right`` is wrong, or None."""
    if not isinstance(op, _COMPARISONS):
        return None
    sides = kinds.time_class(left), kinds.time_class(right)
    if None not in sides:
        if sides[0] != sides[1] and isinstance(op, _ORDERING):
            return f"orders an rclpy `{sides[0]}` against a `{sides[1]}`: rclpy raises TypeError"
        return None
    cls = sides[0] or sides[1]
    if cls is None or not kinds.number(right if sides[0] else left):
        return None
    if isinstance(op, _ORDERING):
        return f"compares an rclpy `{cls}` with a plain number: rclpy raises TypeError"
    return (f"compares an rclpy `{cls}` with a plain number: never equal on Jazzy and later, "
            "TypeError on Humble")


def _conversion(func: ast.expr, index: Index) -> str | None:
    """The name of the builtin (not rebound) or ``math`` function ``func`` calls, if one of
    those that take a real number."""
    if isinstance(func, ast.Name) and func.id in _BUILTINS and func.id not in index.bound:
        return func.id
    name = index.qualified(func) if isinstance(func, ast.Attribute) else None
    return name if name in _MATH else None


def _misuses(tree: ast.Module, index: Index, kinds: _Kinds) -> Iterator[tuple[ast.expr, str]]:
    """(expression, what is wrong) for each use of a time class as a number in ``tree``."""
    for node in nodes_of_class(tree, ast.BinOp, ast.Compare, ast.UnaryOp):
        if isinstance(node, ast.BinOp):
            why = _arithmetic(node, kinds)
            if why:
                yield node, f"{why}: rclpy raises TypeError"
            yield from _percent_formats(node, kinds)
        elif isinstance(node, ast.Compare):
            for left, op, right in zip([node.left, *node.comparators], node.ops,
                                       node.comparators):
                why = _comparison(left, op, right, kinds)
                if why:
                    yield node, why
        elif isinstance(node.op, (ast.USub, ast.UAdd)) and \
                (cls := kinds.time_class(node.operand)):
            yield node, f"negates an rclpy `{cls}`: TypeError"
    for call in index.calls:
        name = _conversion(call.func, index)
        if name and call.args and (cls := kinds.time_class(call.args[0])):
            yield call, (f"gives an rclpy `{cls}` to `{name}()`, which takes a real number: "
                         "TypeError")
    for value, spec, converted in format_specs(tree, index):
        if not converted and (cls := kinds.time_class(value)):
            yield value, (f"is an rclpy `{cls}` formatted with `{spec}`, which it refuses: "
                          "TypeError")


def _percent_formats(node: ast.BinOp, kinds: _Kinds) -> Iterator[tuple[ast.expr, str]]:
    """The time classes ``'...' % values`` formats with a number conversion (``%f``)."""
    for value, conversion in percent_values(node):
        if conversion["type"] not in _TEXT_CONVERSIONS and (cls := kinds.time_class(value)):
            yield value, (f"is an rclpy `{cls}` formatted with `{conversion.group(0)}`, which "
                          "needs a number: TypeError")


@rule("PYC056", "time-used-as-number", Severity.ERROR,
      fix="Use `Duration(seconds=...)` for an amount of time, or `.nanoseconds / 1e9` for a "
          "number of seconds")
def time_used_as_number(package: Package) -> Iterator[Hit]:
    """An rclpy `Time` or `Duration` is computed, compared or formatted as a plain number.

    ## What it does
    Reports an rclpy `Time` or `Duration` (a clock's `now()`, `Time(...)`, `Duration(...)`,
    their differences and sums, and names or `self.x` every assignment of which is one) that
    is added to or subtracted from a number, compared with a number (`elapsed > 2.0`),
    ordered against the other class, given to `float()`, `int()`, `round()`, `abs()` or a
    `math` function, negated, or formatted with a specification (`f'{now:.2f}'`, `'%f' %
    now`); also two `Time`s added. A number is a literal, `time.time()`, or a name or
    attribute all of whose assignments give one. `Duration * number` is left alone (Rolling
    scales durations).

    ## Why is this bad?
    rclpy's time classes only combine with each other (a `Time` minus a `Time` is a
    `Duration`, a `Time` plus a `Duration` a `Time`) and compare with their own class:
    `now - 1.0` and `elapsed > 2.0` raise `TypeError`, and so do `float(now)` and
    `f'{elapsed:.1f}'`. `elapsed == 0` is never true on Jazzy and later (and raises on
    Humble). The callback dies the first time it runs.

    ## Example
    ```python
    if self.get_clock().now() - self.start > 2.0:
        self.get_logger().info('two seconds passed')
    ```

    ## Use instead
    ```python
    if (self.get_clock().now() - self.start).nanoseconds / 1e9 > 2.0:
        self.get_logger().info('two seconds passed')
    ```
    """
    for module, tree, index in installed_trees(package):
        if not index.imports_from("rclpy"):
            continue
        kinds = _Kinds(package, tree, index)
        for node, why in _misuses(tree, index, kinds):
            shown = ast.unparse(node)
            shown = shown if len(shown) <= 50 else shown[:47] + "..."
            yield Hit(Span(module.path, node.lineno, node.col_offset + 1), f"`{shown}` {why}")
