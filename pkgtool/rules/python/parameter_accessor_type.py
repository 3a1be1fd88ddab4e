"""PYC028: a parameter read through the typed field of another type than it is declared, or
through an accessor that does not exist."""

from __future__ import annotations

import ast
from collections.abc import Iterator
from difflib import get_close_matches

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_parameters import module_nodes
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, installed_trees

_FIELDS = {"bool_value": "BOOL", "integer_value": "INTEGER", "double_value": "DOUBLE",
           "string_value": "STRING", "byte_array_value": "BYTE_ARRAY",
           "bool_array_value": "BOOL_ARRAY", "integer_array_value": "INTEGER_ARRAY",
           "double_array_value": "DOUBLE_ARRAY", "string_array_value": "STRING_ARRAY"}
"""The fields of rcl_interfaces' ParameterValue and the parameter type each holds."""


_MESSAGE = frozenset({"type", "SLOT_TYPES", "get_fields_and_field_types"})
"""The other public attributes of a ParameterValue message."""
_PARAMETER = frozenset({"name", "value", "type_", "get_parameter_value", "to_parameter_msg",
                        "from_parameter_msg", "Type"})
"""The public attributes of rclpy's ``Parameter`` (Humble to Rolling), what ``get_parameter``
gives."""


def _self_read(call: ast.expr) -> str | None:
    """``x`` of ``self.get_parameter('x')``."""
    if isinstance(call, ast.Call) and isinstance(call.func, ast.Attribute) and \
            call.func.attr == "get_parameter" and isinstance(call.func.value, ast.Name) and \
            call.func.value.id == "self" and len(call.args) == 1 and \
            isinstance(call.args[0], ast.Constant) and isinstance(call.args[0].value, str):
        return call.args[0].value
    return None


def _missing_accessor(node: ast.Attribute, index: Index) -> str | None:
    """What is wrong with ``self.get_parameter('x').value()`` and with
    ``...get_parameter_value().<attribute ParameterValue has not>``; else None."""
    parent = index.parents.get(id(node))
    name = _self_read(node.value)
    if node.attr == "value" and isinstance(parent, ast.Call) and parent.func is node and \
            name is not None:
        return (f"`{name}` is read with `.value()`: `value` is a property, calling the "
                "parameter's value raises TypeError")
    held = node.value
    through = _self_read(held.value) if isinstance(held, ast.Attribute) and \
        held.attr == "value" else None
    if through is not None and (node.attr in _FIELDS or node.attr == "get_parameter_value"):
        return (f"`{through}` is read with `.value.{node.attr}`: `.value` is already the "
                f"parameter's value (a float, str, ...), which has no `{node.attr}`: it raises "
                "AttributeError")
    if name is not None and node.attr not in _PARAMETER and not node.attr.startswith("_"):
        close = get_close_matches(node.attr, sorted(_PARAMETER), n=1)
        meant = f" (did you mean `{close[0]}`?)" if close else ""
        return (f"`{name}` is read through `{node.attr}`, which rclpy's `Parameter` has not: "
                f"it raises AttributeError{meant}")
    if node.attr in _FIELDS or node.attr in _MESSAGE or node.attr.startswith("_"):
        return None
    name = _typed_read(node)
    return (f"`{name}` is read through `{node.attr}`, which `ParameterValue` has not: it "
            "raises AttributeError (its fields are `bool_value`, `integer_value`, "
            "`double_value`, `string_value`, ...)") if name is not None else None


def _typed_read(node: ast.Attribute) -> str | None:
    """``x`` of ``self.get_parameter('x').get_parameter_value().<field>``."""
    call = node.value
    if not (isinstance(call, ast.Call) and isinstance(call.func, ast.Attribute)
            and call.func.attr == "get_parameter_value" and not call.args):
        return None
    return _self_read(call.func.value)


@rule("PYC028", "parameter-accessor-type", Severity.ERROR,
      fix="Read the field of the declared type (`double_value` for a `0.5` default), or `.value`")
def parameter_accessor_type(package: Package) -> Iterator[Hit]:
    """A parameter is read through the `ParameterValue` field of another type.

    ## What it does
    In `Node` subclasses, reports `self.get_parameter('x').get_parameter_value().<kind>_value`
    when `x` is declared by the module with a literal default of another type
    (`declare_parameter('speed', 1)` is an integer, read with `.double_value`); parameters
    declared with dynamic typing, with no literal default, or with defaults of several types
    are not judged. Also reports reads through an accessor that does not exist: a field
    `ParameterValue` has not (`.get_parameter_value().str_value`, `.int_value`), an
    attribute rclpy's `Parameter` has not (`self.get_parameter('x').values`) and
    `self.get_parameter('x').value()`, which calls the value, and
    `self.get_parameter('x').value.double_value`, which takes a field of the value.

    ## Why is this bad?
    `ParameterValue` has one field per type and only the declared type's is set: the others
    hold their zero value. The node silently works with `0.0`, `0`, `''` or `False` instead
    of the configured value (a timer period of 0, a speed of 0). A field that does not exist
    raises `AttributeError`, and `.value()` raises `TypeError` (`'str' object is not
    callable`): the node dies where it reads the parameter.

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
        for node in index.attributes if classes else ():
            missing = _missing_accessor(node, index)
            around = index.enclosing_class(node) if missing is not None else None
            if missing is not None and around is not None and around.name in classes:
                yield Hit(Span(module.path, node.end_lineno or node.lineno,
                               (node.end_col_offset or 0) - len(node.attr) + 1), missing,
                          "Read `.value`, or the `ParameterValue` field of the declared type")
                continue
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
