"""PYC038: an rclpy ``Duration`` given where rclpy or ``time.sleep`` wants a number."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import argument, node_api_calls
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, installed_trees

DURATIONS = frozenset({"rclpy.duration.Duration", "rclpy.time.Duration"})
"""rclpy's ``Duration`` class, by the names a module imports it through."""
_NUMBERS = {"create_timer": ("timer_period_sec", "seconds"),
            "create_rate": ("frequency", "hertz")}
"""Node methods (Humble to Rolling) whose first parameter is a plain number, and its unit."""
_SLEEPS = frozenset({"time.sleep"})


def _made_durations(function: ast.AST, index: Index) -> set[str]:
    """The local names every assignment in ``function`` gives a ``Duration(...)``."""
    made: dict[str, bool] = {}
    for statement in nodes_of_class(function, ast.Assign, ast.AnnAssign, ast.AugAssign):
        targets = statement.targets if isinstance(statement, ast.Assign) else [statement.target]
        for target in targets:
            if isinstance(target, ast.Name):
                duration = not isinstance(statement, ast.AugAssign) and \
                    statement.value is not None and _constructed(statement.value, index)
                made[target.id] = made.get(target.id, True) and duration
    return {name for name, always in made.items() if always}


def _constructed(value: ast.expr, index: Index) -> bool:
    """True for a call of rclpy's ``Duration``."""
    return isinstance(value, ast.Call) and isinstance(value.func, (ast.Name, ast.Attribute)) \
        and index.qualified(value.func) in DURATIONS


def _a_duration(value: ast.expr | None, index: Index) -> bool:
    """True for ``Duration(...)``, or a local name only ever bound to one."""
    if value is None:
        return False
    if _constructed(value, index):
        return True
    function = index.enclosing_function(value) if isinstance(value, ast.Name) else None
    return function is not None and value.id in _made_durations(function, index)  # type: ignore


def _numbers(package: Package) -> Iterator[tuple[str, ast.expr, str, str]]:
    """(module path, argument, what it is given to, the unit wanted) of every call that wants
    a number of seconds or hertz."""
    for module, call, method, index in node_api_calls(package, _NUMBERS):
        name, unit = _NUMBERS[method]
        given = argument(call, (name,), name)
        if _a_duration(given, index):
            assert given is not None
            yield module.path, given, f"`{method}()`", unit
    for module, _, index in installed_trees(package):
        for call in index.calls:
            if isinstance(call.func, (ast.Name, ast.Attribute)) and \
                    index.qualified(call.func) in _SLEEPS and len(call.args) == 1 and \
                    _a_duration(call.args[0], index):
                yield module.path, call.args[0], "`time.sleep()`", "seconds"


@rule("PYC038", "duration-as-seconds", Severity.ERROR,
      fix="Give the number of seconds (`0.5`), or `duration.nanoseconds / 1e9`")
def duration_as_seconds(package: Package) -> Iterator[Hit]:
    """An rclpy `Duration` is given where a plain number of seconds (or hertz) goes.

    ## What it does
    Reports an rclpy `Duration` (a `Duration(...)` call, or a local name every assignment of
    which is one) given as the period of `create_timer()`, the frequency of `create_rate()`
    or the seconds of `time.sleep()`.

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
