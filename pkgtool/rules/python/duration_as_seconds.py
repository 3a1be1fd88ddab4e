"""PYC038: an rclpy ``Duration`` given where rclpy or ``time.sleep`` wants a number."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import argument, node_api_calls
from pkgtool.rules.python._rclpy_objects import DURATION, object_class
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, installed_tree_of, installed_trees

_NUMBERS = {"create_timer": ("timer_period_sec", "seconds"),
            "create_rate": ("frequency", "hertz")}
"""Node methods (Humble to Rolling) whose first parameter is a plain number, and its unit."""
_SLEEPS = frozenset({"time.sleep"})


def _a_duration(value: ast.expr | None, package: Package, tree: ast.Module,
                index: Index) -> bool:
    """True for a value that certainly is an rclpy ``Duration``."""
    return value is not None and object_class(value, package, tree, index) == DURATION


def _numbers(package: Package) -> Iterator[tuple[str, ast.expr, str, str]]:
    """(module path, argument, what it is given to, the unit wanted) of every call that wants
    a number of seconds or hertz."""
    trees = installed_tree_of(package)
    for module, call, method, index in node_api_calls(package, _NUMBERS):
        name, unit = _NUMBERS[method]
        given = argument(call, (name,), name)
        if _a_duration(given, package, trees[id(index)], index):
            assert given is not None
            yield module.path, given, f"`{method}()`", unit
    for module, tree, index in installed_trees(package):
        for call in index.calls:
            if isinstance(call.func, (ast.Name, ast.Attribute)) and \
                    index.qualified(call.func) in _SLEEPS and len(call.args) == 1 and \
                    _a_duration(call.args[0], package, tree, index):
                yield module.path, call.args[0], "`time.sleep()`", "seconds"


@rule("PYC038", "duration-as-seconds", Severity.ERROR,
      fix="Give the number of seconds (`0.5`), or `duration.nanoseconds / 1e9`")
def duration_as_seconds(package: Package) -> Iterator[Hit]:
    """An rclpy `Duration` is given where a plain number of seconds (or hertz) goes.

    ## What it does
    Reports an rclpy `Duration` (a `Duration(...)` call, a difference of two times, or a name
    or `self.x` every assignment of which is one) given as the period of `create_timer()`,
    the frequency of `create_rate()` or the seconds of `time.sleep()`.

    ## Why is this bad?
    These take a float: `create_timer(Duration(seconds=0.5), cb)` raises `TypeError: float()
    argument must be a string or a real number, not 'Duration'`, `create_rate(Duration(...))`
    raises `TypeError` on comparing it with 0, and so does `time.sleep()`. The node dies as it
    starts. (A `Duration` is what rclpy's clocks and `Time` arithmetic use; these calls predate
    it.)

    ## Example
    ```python
    self.timer = self.create_timer(Duration(seconds=0.5), self.tick)
    ```

    ## Use instead
    ```python
    self.timer = self.create_timer(0.5, self.tick)
    ```
    """
    for path, given, where, unit in _numbers(package):
        yield Hit(Span(path, given.lineno, given.col_offset + 1),
                  f"A `Duration` is given to {where}, which takes a number of {unit}: "
                  "rclpy raises TypeError")
