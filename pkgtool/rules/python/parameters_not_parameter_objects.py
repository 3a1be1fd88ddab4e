"""PYC054: a node's ``set_parameters()`` given what is not a list of ``Parameter`` objects."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import argument, literal_type, node_api_calls
from pkgtool.rules.node_parameters import PARAMETER_CLASSES, SETS
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index

_LIST = ("parameter_list",)
"""The setters' one parameter (Humble to Rolling)."""


def _refused(value: ast.expr, index: Index) -> str | None:
    """Why rclpy refuses ``value`` as the list of parameters, or None when it may not."""
    if isinstance(value, (ast.List, ast.Tuple)):
        item = next((e for e in value.elts if not isinstance(e, ast.Starred) and
                     literal_type(e) is not None), None)
        return f"its item `{ast.unparse(item)}` is a {literal_type(item)}, not a `Parameter`" \
            if item is not None else None
    if isinstance(value, ast.Call) and isinstance(value.func, (ast.Name, ast.Attribute)) and \
            index.qualified(value.func) in PARAMETER_CLASSES:
        return "it is one `Parameter`, not a list of them"
    kind = literal_type(value)
    return f"it is a {kind}, not a list of `Parameter`s" if kind is not None else None


@rule("PYC054", "set-parameters-without-parameter", Severity.ERROR,
      fix="Pass a list of `rclpy.parameter.Parameter` objects")
def set_parameters_without_parameter(package: Package) -> Iterator[Hit]:
    """A node's `set_parameters()` is given something other than a list of `Parameter`s.

    ## What it does
    Reports `node.set_parameters(...)` and `node.set_parameters_atomically(...)` whose
    argument is certainly wrong: a list or tuple display with an item that is a literal (a
    `('speed', 1.0)` pair, a name string, a dict, a number), a single `Parameter(...)` not in
    a list, or a literal itself (a dict, a string).

    ## Why is this bad?
    rclpy takes a list of `rclpy.parameter.Parameter` objects and refuses anything else with
    `TypeError` (Jazzy: `parameter must be instance of type Parameter`; a single `Parameter`:
    `'Parameter' object is not iterable`): the node dies where it meant to change its own
    settings, often in a callback.

    ## Example
    ```python
    self.set_parameters([('speed', 1.0)])
    ```

    ## Use instead
    ```python
    from rclpy.parameter import Parameter

    self.set_parameters([Parameter('speed', value=1.0)])
    ```
    """
    for module, call, method, index in node_api_calls(package, SETS):
        value = argument(call, _LIST, _LIST[0])
        why = _refused(value, index) if value is not None else None
        if why is not None:
            yield Hit(Span(module.path, call.lineno, call.col_offset + 1),
                      f"`{method}()` takes a list of `Parameter` objects, but {why}: "
                      "rclpy raises TypeError")
