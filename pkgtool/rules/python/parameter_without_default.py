"""PYC060: a parameter declared with only its name (no default value, no type)."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import argument, node_api_calls, unpacks
from pkgtool.rules.python._assignments import is_none
from pkgtool.rules.registry import rule

DECLARE = ("name", "value", "descriptor", "ignore_override")
"""``Node.declare_parameter``'s parameters, in order."""
DECLARE_MANY = ("namespace", "parameters", "ignore_override")
"""``Node.declare_parameters``' parameters, in order."""


def _name_only(call: ast.Call) -> ast.expr | None:
    """The name ``declare_parameter(name)`` is given when it gives no value (or None) and no
    descriptor."""
    value, descriptor = argument(call, DECLARE, "value"), argument(call, DECLARE, "descriptor")
    if (value is None or is_none(value)) and descriptor is None:
        return argument(call, DECLARE, "name")
    return None


def _one_tuples(call: ast.Call) -> Iterator[ast.expr]:
    """The names ``declare_parameters(namespace, [...])`` gives in tuples of one."""
    parameters = argument(call, DECLARE_MANY, "parameters")
    if isinstance(parameters, (ast.List, ast.Tuple)):
        for item in parameters.elts:
            if isinstance(item, ast.Tuple) and len(item.elts) == 1 and \
                    not isinstance(item.elts[0], ast.Starred):
                yield item.elts[0]


@rule("PYC060", "parameter-without-default", Severity.WARNING,
      fix="Give a default value (`declare_parameter('rate', 10.0)`) or a type "
          "(`declare_parameter('rate', Parameter.Type.DOUBLE)`)")
def parameter_without_default(package: Package) -> Iterator[Hit]:
    """A node declares a parameter with only its name: no default value and no type.

    ## What it does
    Reports `declare_parameter(name)` with no value (or `None`) and no descriptor, and the
    tuples of one, `(name,)`, in a list given to `declare_parameters()`. Calls that unpack
    `*args` or `**kwargs`, or pass a keyword rclpy does not take (PYC029), are left alone.

    ## Why is this bad?
    Since ROS 2 Galactic, rclpy warns at start-up that declaring a parameter with only its
    name is deprecated (a `UserWarning` naming the parameter). Such a parameter has no type
    and, unless a parameter file or launch file sets it, its value is None: the first use as
    a number (`create_timer(period, ...)`, `speed * 2`) raises `TypeError`.

    ## Example
    ```python
    self.declare_parameter('period')
    period = self.get_parameter('period').value
    ```

    ## Use instead
    ```python
    self.declare_parameter('period', 0.5)
    period = self.get_parameter('period').value
    ```
    """
    methods = ("declare_parameter", "declare_parameters")
    for module, call, method, _ in node_api_calls(package, methods):
        taken = DECLARE if method == "declare_parameter" else DECLARE_MANY
        if unpacks(call) or any(k.arg not in taken for k in call.keywords):
            continue  # PYC029 reports a keyword rclpy does not take
        names = [_name_only(call)] if method == "declare_parameter" else _one_tuples(call)
        for name in names:
            if name is None:
                continue
            shown = repr(name.value) if isinstance(name, ast.Constant) else ast.unparse(name)
            yield Hit(Span(module.path, name.lineno, name.col_offset + 1),
                      f"Parameter {shown} is declared with only its name: rclpy warns this is "
                      "deprecated, and its value is None unless a parameter file sets it")
