"""PYC070: an rclpy ``Parameter`` built with a type its value does not have."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import argument, unpacks
from pkgtool.rules.python._code_and_tests import code_and_test_indexes
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index

_PARAMETER = "rclpy.parameter.Parameter"
_TYPE = f"{_PARAMETER}.Type."
_FOREIGN_TYPES = ("rcl_interfaces.msg.ParameterType.", "rcl_interfaces.msg._parameter_type.")
"""Where the message constants (``ParameterType.PARAMETER_DOUBLE``) come from: ints, which
``Parameter`` refuses as its type."""
_ITEMS = {"BOOL_ARRAY": (bool,), "INTEGER_ARRAY": (int,), "DOUBLE_ARRAY": (float,),
          "STRING_ARRAY": (str,), "BYTE_ARRAY": (bytes,)}
_SCALARS = {"BOOL": (bool,), "INTEGER": (int,), "DOUBLE": (float,), "STRING": (str,),
            "NOT_SET": (type(None),)}
"""``Parameter.Type.check`` of rclpy (Humble to Rolling): the Python types each accepts (an
array: a list or tuple of these; ``True`` is an int, as in Python)."""
_NO_VALUE = object()


def _literal(value: ast.expr | None) -> object:
    """The Python value of a literal (None when no value is given), else ``_NO_VALUE``."""
    if value is None:
        return None
    try:
        return ast.literal_eval(value)
    except (ValueError, TypeError, SyntaxError, MemoryError, RecursionError):
        return _NO_VALUE


def _agrees(kind: str, value: object) -> bool:
    if kind in _SCALARS:
        return isinstance(value, _SCALARS[kind])
    items = _ITEMS.get(kind)
    return items is None or isinstance(value, (list, tuple)) and all(
        isinstance(v, items) and (not isinstance(v, bytes) or len(v) == 1) for v in value)


_EXPECTING = frozenset({"raises", "assertRaises", "assertRaisesRegex"})
_CAUGHT = frozenset({"ValueError", "TypeError", "Exception", "BaseException"})


def _expected(call: ast.Call, index: Index) -> bool:
    """True inside ``with pytest.raises(...)`` (or ``assertRaises``), or in the body of a
    ``try`` that catches ValueError or TypeError: the error is what the code waits for."""
    child, parent = call, index.parents.get(id(call))
    while parent is not None:
        if isinstance(parent, (ast.With, ast.AsyncWith)) and any(
                isinstance(i.context_expr, ast.Call) and
                isinstance(i.context_expr.func, (ast.Attribute, ast.Name)) and
                ast.unparse(i.context_expr.func).rsplit(".", 1)[-1] in _EXPECTING
                for i in parent.items):
            return True
        if isinstance(parent, ast.Try) and any(child is s for s in parent.body) and any(
                h.type is None or {n.id for n in ast.walk(h.type) if isinstance(n, ast.Name)}
                & _CAUGHT for h in parent.handlers):
            return True
        child, parent = parent, index.parents.get(id(parent))
    return False


def _problem(call: ast.Call, index: Index) -> tuple[ast.expr, str, str] | None:
    """(where, what happens, the fix) for a ``Parameter(name, type_, value)`` call rclpy
    refuses, or None."""
    type_ = argument(call, ("name", "type_", "value"), "type_")
    value = argument(call, ("name", "type_", "value"), "value")
    if type_ is None:
        return None
    named = index.qualified(type_) if isinstance(type_, (ast.Name, ast.Attribute)) else None
    if named and named.startswith(_FOREIGN_TYPES):
        leaf = named.rsplit(".", 1)[-1].removeprefix("PARAMETER_")
        return (type_, f"`{ast.unparse(type_)}` is a message constant (an int), not a "
                f"`Parameter.Type`: rclpy raises TypeError", f"Use `Parameter.Type.{leaf}`")
    if named is None or not named.startswith(_TYPE):
        literal = _literal(type_)
        if literal is _NO_VALUE or literal is None or value is not None:
            return None
        return (type_, f"`{ast.unparse(type_)}` is given as the type (the second argument), "
                "not a `Parameter.Type`: rclpy raises TypeError",
                f"Write `value={ast.unparse(type_)}`")
    kind, given = named[len(_TYPE):], _literal(value)
    if given is _NO_VALUE or _agrees(kind, given):
        return None
    shown = "no value" if value is None else f"the value `{ast.unparse(value)}`"
    fix = f"Write `{given!r}.0`" if kind == "DOUBLE" and type(given) is int else \
        "Give a value of that type"
    return (value or call, f"`Parameter.Type.{kind}` with {shown}: rclpy raises ValueError "
            "(the type and the value do not agree)", fix)


@rule("PYC070", "parameter-type-disagrees", Severity.ERROR,
      fix="Give `Parameter` a `Parameter.Type` and a value of that type")
def parameter_type_disagrees(package: Package) -> Iterator[Hit]:
    """An rclpy `Parameter` is built with a type its value does not have.

    ## What it does
    In installed modules and tests, reports `rclpy.parameter.Parameter(name, type_, value)`
    calls that rclpy refuses: a literal value (or no value) that the `Parameter.Type` given
    does not accept (`Parameter.Type.DOUBLE` with `2`: rclpy wants a float; a type with no
    value, which is None), a type from the `ParameterType` message (an int), and a literal
    value given in the place of the type (`Parameter('rate', 10.0)`). A value that is not
    a literal is left alone, and so is a call where the error is awaited (under
    `pytest.raises`, in a `try` catching ValueError or TypeError).

    ## Why is this bad?
    `Parameter.__init__` checks the pair: the call raises `ValueError` ("Type ... and value
    ... do not agree") or `TypeError`, usually in the node's start-up or in the callback that
    sets the parameter, which then never takes effect.

    ## Example
    ```python
    self.set_parameters([Parameter('speed', Parameter.Type.DOUBLE, 2)])
    ```

    ## Use instead
    ```python
    self.set_parameters([Parameter('speed', Parameter.Type.DOUBLE, 2.0)])
    ```
    """
    for module, index in code_and_test_indexes(package):
        path = module.path
        if not index.imports_from("rclpy"):
            continue
        for call in index.calls:
            if unpacks(call) or not isinstance(call.func, (ast.Name, ast.Attribute)) or \
                    index.qualified(call.func) != _PARAMETER or _expected(call, index):
                continue
            found = _problem(call, index)
            if found is not None:
                where, message, fix = found
                yield Hit(Span(path, where.lineno, where.col_offset + 1), message, fix)
