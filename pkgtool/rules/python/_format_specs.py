"""Where code formats a value with a written-out format specification (PYC040, PYC051)."""

from __future__ import annotations

import ast
import re
import string
from collections.abc import Iterator

from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.rules.node_api import unpacks
from pkgtool.rules.syntax_trees import Index
from pkgtool.lazy_regex import lazy_pattern

PERCENT = lazy_pattern(r"%(?:\((?P<key>[^)]*)\))?[-#0 +]*(?P<width>\*|\d+)?"
                       r"(?:\.(?P<precision>\*|\d*))?[hlL]?(?P<type>[diouxXeEfFgGcrsa%])")
"""One ``%`` conversion of printf-style formatting."""


def _literal_spec(spec: ast.expr | None) -> str | None:
    """An f-string field's format specification when it is written out (no ``{width}``)."""
    if not isinstance(spec, ast.JoinedStr) or not all(
            isinstance(v, ast.Constant) and isinstance(v.value, str) for v in spec.values):
        return None
    return "".join(v.value for v in spec.values)  # type: ignore[attr-defined]


def _format_calls(index: Index) -> Iterator[tuple[ast.expr, str, bool]]:
    """(value, specification, converted) of each ``'...'.format(...)`` field and each
    ``format(value, '...')`` with a written-out specification."""
    for call in index.calls:
        func = call.func
        if isinstance(func, ast.Name) and func.id == "format" and "format" not in index.bound \
                and len(call.args) == 2 and not call.keywords and \
                isinstance(call.args[1], ast.Constant) and isinstance(call.args[1].value, str):
            if call.args[1].value:
                yield call.args[0], call.args[1].value, False
        elif isinstance(func, ast.Attribute) and func.attr == "format" and \
                isinstance(func.value, ast.Constant) and isinstance(func.value.value, str):
            yield from _format_fields(func.value.value, call)


def _format_fields(template: str, call: ast.Call) -> Iterator[tuple[ast.expr, str, bool]]:
    if unpacks(call):
        return
    keywords = {k.arg: k.value for k in call.keywords}
    try:
        fields = list(string.Formatter().parse(template))
    except ValueError:
        return
    automatic = 0
    for _, field, spec, conversion in fields:
        if field is None:
            continue
        value: ast.expr | None = None
        if field == "":
            value = call.args[automatic] if automatic < len(call.args) else None
            automatic += 1
        elif field.isdecimal():
            value = call.args[int(field)] if int(field) < len(call.args) else None
        elif field.isidentifier():
            value = keywords.get(field)
        if value is not None and spec and "{" not in spec:
            yield value, spec, bool(conversion)


def format_specs(tree: ast.Module, index: Index) -> Iterator[tuple[ast.expr, str, bool]]:
    """(value, specification, converted) of every value formatted with a written-out format
    specification: f-string fields, ``'...'.format(...)`` fields, ``format(value, '...')``;
    ``converted``: ``!r``/``!s``/``!a`` made the value a str first."""
    for field in nodes_of_class(tree, ast.FormattedValue):
        spec = _literal_spec(field.format_spec)  # type: ignore[attr-defined]
        if spec:
            yield field.value, spec, field.conversion != -1  # type: ignore[attr-defined]
    yield from _format_calls(index)


def percent_values(node: ast.BinOp) -> Iterator[tuple[ast.expr, re.Match[str]]]:
    """(value, its conversion) of each conversion of ``'...' % values`` (the template a str
    literal), when conversions and values pair up one to one (no ``%(key)s``, no ``*``)."""
    if not (isinstance(node.op, ast.Mod) and isinstance(node.left, ast.Constant) and
            isinstance(node.left.value, str)):
        return
    conversions = [m for m in PERCENT.finditer(node.left.value) if m["type"] != "%"]
    if not conversions or any(m["key"] is not None or m["width"] == "*" or
                              m["precision"] == "*" for m in conversions):
        return
    values = node.right.elts if isinstance(node.right, ast.Tuple) else [node.right]
    if any(isinstance(v, ast.Starred) for v in values) or len(values) != len(conversions):
        return
    yield from zip(values, conversions)
