"""PYC034: ``rate.sleep()`` where nothing can spin the node whose timer wakes the Rate."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.imports import entry_points_installed
from pkgtool.rules.node_api import node_subclasses
from pkgtool.rules.registry import rule
from pkgtool.rules.scopes import scope_walk
from pkgtool.rules.syntax_trees import FUNCTIONS, installed_trees

_THREADS = frozenset({"threading", "_thread", "concurrent", "multiprocessing", "asyncio"})
"""Modules through which code may spin a node in another thread (or process, or loop)."""
Function = ast.FunctionDef | ast.AsyncFunctionDef


def _rate_made(value: ast.expr | None) -> bool:
    """True for a call ``<x>.create_rate(...)``."""
    return isinstance(value, ast.Call) and isinstance(value.func, ast.Attribute) and \
        value.func.attr == "create_rate"


def _stored(target: ast.expr) -> str | None:
    """``r`` for a local ``r``, ``.r`` for an attribute ``self.r``; None for other targets."""
    return target.id if isinstance(target, ast.Name) else \
        f".{target.attr}" if isinstance(target, ast.Attribute) else None


def _sleeps(function: Function) -> Iterator[ast.Call]:
    """``r.sleep()`` calls of ``function`` on a Rate it makes itself (``r =
    x.create_rate(...)``, ``self.r = ...``, or ``x.create_rate(...).sleep()``); none when it
    spins anything (``rclpy.spin_once(self)`` before each sleep wakes the Rate)."""
    nodes = list(scope_walk(function.body))
    calls = [n for n in nodes if isinstance(n, ast.Call)]
    if any((c.func.attr if isinstance(c.func, ast.Attribute) else
            getattr(c.func, "id", "")).startswith("spin") for c in calls):
        return
    rates = {_stored(t) for n in nodes if isinstance(n, ast.Assign) and _rate_made(n.value)
             for t in n.targets} - {None}
    for call in calls:
        func = call.func
        if isinstance(func, ast.Attribute) and func.attr == "sleep" and not call.args and \
                (_rate_made(func.value) or _stored(func.value) in rates):
            yield call


@rule("PYC034", "rate-sleep-without-spin", Severity.ERROR,
      fix="Use a timer (`self.create_timer(period, self.step)`) instead of a loop, or spin "
          "the node in another thread before the loop")
def rate_sleep_without_spin(package: Package) -> Iterator[Hit]:
    """`rate.sleep()` waits for a node that nothing spins, and never returns.

    ## What it does
    Reports `sleep()` on a Rate that `create_rate()` made in the same function, when that
    function is the `__init__` of a `Node` subclass or a console script's entry function,
    the function spins nothing itself (no `spin`, `spin_once`, ...), and no installed module
    of the package imports `threading`, `concurrent`, `multiprocessing`, `_thread` or
    `asyncio` (a thread may spin the node then, as in rclpy's own Rate example).

    ## Why is this bad?
    rclpy's `Rate` sleeps until a timer of its node fires, and a timer fires only while an
    executor spins the node. In `__init__` the node cannot be spinning yet, and in `main`
    before `rclpy.spin()` nothing spins it: the first `rate.sleep()` blocks until ROS shuts
    down, with no error; the node does nothing (checked on Jazzy).

    ## Example
    ```python
    def __init__(self):
        super().__init__('talker')
        rate = self.create_rate(10)
        while rclpy.ok():
            self.publish()
            rate.sleep()
    ```

    ## Use instead
    ```python
    def __init__(self):
        super().__init__('talker')
        self.timer = self.create_timer(0.1, self.publish)
    ```
    """
    trees = installed_trees(package)
    if any(i.top_level in _THREADS for module, _, _ in trees for i in module.imports):
        return
    entries = {(path, entry.attr) for entry, path in
               entry_points_installed(package, "console_scripts") if entry.valid}
    for module, tree, index in trees:
        functions = [f for cls in node_subclasses(index) for f in cls.body
                     if isinstance(f, FUNCTIONS) and f.name == "__init__"]
        functions += [f for f in tree.body if isinstance(f, FUNCTIONS) and
                      (module.path, f.name) in entries]
        for function in functions:
            for call in _sleeps(function):
                yield Hit(Span(module.path, call.lineno, call.col_offset + 1),
                          f"`{ast.unparse(call)}` waits for a timer of the node, which fires "
                          "only while the node spins, and nothing spins it here"
                          f"{' (in `__init__`)' if function.name == '__init__' else ''}: "
                          "it never returns")
