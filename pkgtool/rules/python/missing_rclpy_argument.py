"""PYC049: a node's create_* or parameter method called without an argument it requires."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import (PARAMETERS, argument, node_api_calls, swapped_argument,
                                    unpacks)
from pkgtool.rules.registry import rule

REQUIRED = {**PARAMETERS,
            "create_timer": ("timer_period_sec", "callback"),
            "create_rate": ("frequency",),
            "declare_parameter": ("name",),
            "get_parameter": ("name",)}
"""rclpy ``Node`` methods (Humble to Rolling) and their required parameters, in order."""
_ORDERED = frozenset({*PARAMETERS, "create_timer"})
"""The methods PYC030 checks the order of the arguments of."""


@rule("PYC049", "missing-rclpy-argument", Severity.ERROR,
      fix="Pass every argument the method requires: `self.create_timer(0.5, self.tick)`")
def missing_rclpy_argument(package: Package) -> Iterator[Hit]:
    """A node's `create_*` or parameter method is called without an argument it requires.

    ## What it does
    Reports `create_timer`, `create_publisher`, `create_subscription`, `create_service`,
    `create_client`, `create_rate`, `declare_parameter` and `get_parameter` calls on a node
    that leave out a required parameter other than `qos_profile` (PYC007 reports that one):
    `self.create_timer(0.5)` without its callback, `self.create_service(Trigger,
    self.on_reset)` without the service name. Calls passing `*args` or `**kwargs`, and
    modules defining a method of the same name, are not checked, nor calls whose arguments
    are out of order (PYC030 reports them).

    ## Why is this bad?
    Python raises `TypeError: create_timer() missing 1 required positional argument:
    'callback'` when the line runs, usually in the node's constructor: the node never
    starts.

    ## Example
    ```python
    self.timer = self.create_timer(0.5)
    ```

    ## Use instead
    ```python
    self.timer = self.create_timer(0.5, self.tick)
    ```
    """
    for module, call, method, index in node_api_calls(package, REQUIRED):
        parameters = REQUIRED[method]
        missing = [p for p in parameters if p != "qos_profile" and
                   argument(call, parameters, p) is None]
        ordered = method in _ORDERED and swapped_argument(call, method, index) is not None
        if missing and not unpacks(call) and not ordered:  # PYC030 reports the order
            names = " and ".join(f"`{p}`" for p in missing)
            yield Hit(Span(module.path, call.lineno, call.col_offset + 1),
                      f"`{ast.unparse(call)}` leaves out {names}, which `{method}()` requires: "
                      f"Python raises TypeError")
