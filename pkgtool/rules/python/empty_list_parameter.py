"""PYC073: a parameter declared with an empty list as its default, which rclpy types as a
byte array."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import argument, node_api_calls
from pkgtool.rules.node_parameters import literal_flag, static_typing
from pkgtool.rules.registry import rule

_DECLARE = ("name", "value", "descriptor", "ignore_override")
"""``Node.declare_parameter``'s parameters, in order (Humble to Rolling)."""
_DECLARE_MANY = ("namespace", "parameters", "ignore_override")


@rule("PYC073", "empty-list-parameter-default", Severity.WARNING,
      fix="Declare the type: `declare_parameter('frames', Parameter.Type.STRING_ARRAY)`, or "
          "give a default of the list's type")
def empty_list_parameter_default(package: Package) -> Iterator[Hit]:
    """A parameter is declared with an empty list as its default.

    ## What it does
    Reports `declare_parameter('name', [])` (also `()`, and `('name', [])` in the list of
    `declare_parameters`) on a node, unless a descriptor makes the parameter dynamically
    typed (`ParameterDescriptor(dynamic_typing=True)`) or `ignore_override=True` keeps
    overrides away.

    ## Why is this bad?
    rclpy infers a parameter's type from its default, and takes an empty list for a
    `BYTE_ARRAY` (every item of no items is `bytes`). The parameter is meant to hold a list
    of names or numbers, so the moment a parameter file or `--ros-args -p` gives it one, the
    node fails at start-up with `InvalidParameterTypeException: Trying to set parameter
    'frames' to '['map', 'odom']' of type 'STRING_ARRAY', expecting type 'BYTE_ARRAY'`
    (checked on Jazzy; ros2/rclpy#912).

    ## Example
    ```python
    self.declare_parameter('frames', [])
    ```

    ## Use instead
    ```python
    from rclpy.parameter import Parameter

    self.declare_parameter('frames', Parameter.Type.STRING_ARRAY)
    ```
    """
    for module, call, method, _ in node_api_calls(package, ("declare_parameter",
                                                            "declare_parameters")):
        if method == "declare_parameter":
            found = [(call, argument(call, _DECLARE, "value"),
                      argument(call, _DECLARE, "descriptor"))]
        else:
            items = argument(call, _DECLARE_MANY, "parameters")
            found = [(item, item.elts[1], item.elts[2] if len(item.elts) > 2 else None)
                     for item in (items.elts if isinstance(items, (ast.List, ast.Tuple))
                                  else ()) if isinstance(item, ast.Tuple) and len(item.elts) > 1]
        if literal_flag(call, "ignore_override") is not False:
            continue
        for where, value, descriptor in found:
            if isinstance(value, (ast.List, ast.Tuple)) and not value.elts and \
                    static_typing(descriptor):
                yield Hit(Span(module.path, where.lineno, where.col_offset + 1),
                          f"`{ast.unparse(value)}` as a default makes the parameter a "
                          "BYTE_ARRAY: giving it a list of names or numbers (a parameter "
                          "file, `-p`) raises InvalidParameterTypeException at start-up")
