"""PYC028: a parameter read through the typed field of another type than it is declared."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_parameters import module_nodes
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import installed_trees

_FIELDS = {"bool_value": "BOOL", "integer_value": "INTEGER", "double_value": "DOUBLE",
           "string_value": "STRING", "byte_array_value": "BYTE_ARRAY",
           "bool_array_value": "BOOL_ARRAY", "integer_array_value": "INTEGER_ARRAY",
           "double_array_value": "DOUBLE_ARRAY", "string_array_value": "STRING_ARRAY"}
"""The fields of rcl_interfaces' ParameterValue and the parameter type each holds."""


def _typed_read(node: ast.Attribute) -> str | None:
    """``x`` of ``self.get_parameter('x').get_parameter_value().<field>``."""
    call = node.value
    if not (isinstance(call, ast.Call) and isinstance(call.func, ast.Attribute)
            and call.func.attr == "get_parameter_value" and not call.args):
        return None
    read = call.func.value
    if isinstance(read, ast.Call) and isinstance(read.func, ast.Attribute) and \
            read.func.attr == "get_parameter" and isinstance(read.func.value, ast.Name) and \
            read.func.value.id == "self" and len(read.args) == 1 and \
            isinstance(read.args[0], ast.Constant) and isinstance(read.args[0].value, str):
        return read.args[0].value
    return None


@rule("PYC028", "parameter-accessor-type", Severity.ERROR,
      fix="Read the field of the declared type (`double_value` for a `0.5` default), or `.value`")
def parameter_accessor_type(package: Package) -> Iterator[Hit]:
    """A parameter is read through the `ParameterValue` field of another type.

    ## What it does
    In `Node` subclasses, reports `self.get_parameter('x').get_parameter_value().<kind>_value`
    when `x` is declared by the module with a literal default of another type
    (`declare_parameter('speed', 1)` is an integer, read with `.double_value`); parameters
    declared with dynamic typing, with no literal default, or with defaults of several types
    are not judged.

    ## Why is this bad?
    `ParameterValue` has one field per type and only the declared type's is set: the others
    hold their zero value. The node silently works with `0.0`, `0`, `''` or `False` instead
    of the configured value (a timer period of 0, a speed of 0).

    ## Example
    ```python
    self.declare_parameter('speed', 1)
    speed = self.get_parameter('speed').get_parameter_value().double_value
    ```

    ## Use instead
    ```python
    self.declare_parameter('speed', 1.0)
    speed = self.get_parameter('speed').get_parameter_value().double_value
    ```
    """
    nodes = module_nodes(package)
    for module, _, index in installed_trees(package):
        classes = {c.name: c for c in nodes[module.path].classes} if module.path in nodes else {}
        for node in index.attributes:
            wanted = _FIELDS.get(node.attr)
            name = _typed_read(node) if wanted else None
            cls = index.enclosing_class(node) if name else None
            found = classes.get(cls.name) if cls is not None else None
            types = {d.type for d in found.declared if d.name == name} if found else set()
            if len(types) == 1 and None not in types and wanted not in types:
                declared = types.pop()
                yield Hit(Span(module.path, node.end_lineno or node.lineno,
                               (node.end_col_offset or 0) - len(node.attr) + 1),
                          f"`{name}` is declared {declared} but read as `{node.attr}`: that "
                          f"field is unset and holds its zero value")
