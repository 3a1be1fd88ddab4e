"""PYC085: a written-out format string that str.format or % formatting always refuses."""

from __future__ import annotations

import ast
import re
import string
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity, shortened
from pkgtool.lazy_regex import lazy_pattern
from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import unpacks
from pkgtool.rules.python._format_specs import PERCENT
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import installed_trees, launch_trees

_FIELD_NAME = lazy_pattern(r"[^.\[]*")
"""The argument part of a replacement field (``name`` of ``name.attr`` or ``name[0]``)."""


@rule("PYC085", "malformed-format-string", Severity.ERROR,
      fix="Mend the format string (balance its braces, use `%%` for a percent sign), or give "
          "it as many values as it has fields")
def malformed_format_string(package: Package) -> Iterator[Hit]:
    """A format string written out in the code is one that formatting always refuses.

    ## What it does
    Checks `'...'.format(...)` calls on a string literal (not given `*args` or `**kwargs`)
    and `'...' % values` on a string literal in installed modules and Python launch files.
    For `str.format`: a malformed string (an unbalanced `{` or `}`, an unknown `!x`
    conversion), automatic and numbered fields mixed (`'{} {1}'`), a field for a positional
    argument the call does not give (`'{} {}'.format(x)`, `'{2}'`) or a name it does not give
    (`'{speed}'.format(v=1)`). For `%`: a conversion Python does not know (`'%z'`, a `%` at
    the end; `'50%'` with `%` formatting), and, when the values are a tuple display, a
    number of values other than the conversions take, or a tuple given to `%(name)s`
    conversions; a single literal value given to several conversions.

    ## Why is this bad?
    The line raises `ValueError` ("Single '}' encountered in format string", "unsupported
    format character"), `IndexError`, `KeyError` or `TypeError` ("not all arguments
    converted during string formatting") every time it runs: usually in a log line or an
    error message, so the node dies on the very path meant to report a problem.

    ## Example
    ```python
    self.get_logger().warn('Voltage {:.2f} over {:.1f} V'.format(voltage))
    self.get_logger().info('Battery at %d%' % level)
    ```

    ## Use instead
    ```python
    self.get_logger().warn('Voltage {:.2f} over {:.1f} V'.format(voltage, limit))
    self.get_logger().info('Battery at %d%%' % level)
    ```
    """
    installed = ((module.path, tree, index) for module, tree, index in installed_trees(package))
    for path, tree, index in [*installed, *launch_trees(package)]:
        for call in index.calls:
            func = call.func
            if isinstance(func, ast.Attribute) and func.attr == "format" and \
                    isinstance(func.value, ast.Constant) and isinstance(func.value.value, str) \
                    and not unpacks(call):
                problem = _format_problem(func.value.value, call)
                if problem is not None:
                    yield _hit(path, call, problem)
        for node in nodes_of_class(tree, ast.BinOp):
            assert isinstance(node, ast.BinOp)
            if not (isinstance(node.left, ast.Constant) and isinstance(node.left.value, str)) \
                    or index.in_unevaluated_annotation(node):
                continue  # `'Node' | None` under `from __future__ import annotations` is text
            problem = _percent_problem(node) if isinstance(node.op, ast.Mod) else \
                _operator_problem(node)
            if problem is not None:
                yield _hit(path, node, problem)


def _format_problem(template: str, call: ast.Call) -> str | None:
    """What ``template.format(...)`` given the arguments of ``call`` raises, or None."""
    try:
        fields = [(name, conversion) for _, name, _, conversion
                  in string.Formatter().parse(template) if name is not None]
    except ValueError as error:
        return f"the format string is malformed ({error}): `str.format` raises ValueError"
    for name, conversion in fields:
        if conversion not in (None, "r", "s", "a"):
            return (f"`!{conversion}` is no conversion (`!r`, `!s` or `!a`): `str.format` "
                    "raises ValueError")
    names = [_FIELD_NAME.match(name).group(0) for name, _ in fields]  # type: ignore[union-attr]
    automatic, numbered = names.count(""), [n for n in names if n.isdecimal()]
    if automatic and numbered:
        return ("automatic fields (`{}`) and numbered ones (`{0}`) are mixed: `str.format` "
                "raises ValueError")
    wanted = max([automatic, *(int(n) + 1 for n in numbered)])
    if wanted > len(call.args):
        return (f"it takes {wanted} positional value{'s' if wanted > 1 else ''} but is given "
                f"{len(call.args)}: `str.format` raises IndexError")
    given = {k.arg for k in call.keywords}
    missing = sorted({n for n in names if n and not n.isdecimal() and n not in given})
    if missing:
        return f"no value is given for `{{{missing[0]}}}`: `str.format` raises KeyError"
    return None


def _percent_problem(node: ast.BinOp) -> str | None:
    """What ``'...' % values`` raises (the template a string literal), or None."""
    template = node.left.value  # type: ignore[attr-defined]
    conversions, at = [], 0
    while (start := template.find("%", at)) >= 0:
        found = PERCENT.match(template, start)
        if found is None and template.startswith("%(", start):
            found = _bracketed_key(template, start)  # `%(a(b))s`: Python counts brackets
        if found is None:
            closing = template.find(")", start) if template.startswith("%(", start) else -1
            shown = template[start:closing + 2] if closing > 0 else template[start:start + 2]
            return (f"`{shown}` is no conversion (write `%%` for a percent sign): `%` "
                    "formatting raises ValueError")
        if found["type"] != "%":
            conversions.append(found)
        at = found.end()
    keyed = any(c["key"] is not None for c in conversions)
    takes = sum(1 + (c["width"] == "*") + (c["precision"] == "*") for c in conversions)
    right = node.right
    if isinstance(right, ast.Tuple) and not any(isinstance(v, ast.Starred) for v in right.elts):
        if keyed:
            return "`%(name)s` conversions take a mapping, not a tuple: `%` raises TypeError"
        if len(right.elts) != takes:
            few = "not enough arguments for" if len(right.elts) < takes else \
                "not all arguments converted during"
            return (f"it has {takes} conversion{'s' if takes != 1 else ''} but is given "
                    f"{len(right.elts)} value{'s' if len(right.elts) != 1 else ''}: `%` raises "
                    f"TypeError ({few} string formatting)")
    elif isinstance(right, ast.Constant) and not keyed and takes != 1:
        return f"it has {takes} conversions but is given one value: `%` raises TypeError"
    return None


_OPERATORS = {ast.BitAnd: "&", ast.BitOr: "|", ast.BitXor: "^", ast.Sub: "-", ast.Div: "/",
              ast.FloorDiv: "//", ast.Pow: "**", ast.LShift: "<<", ast.RShift: ">>",
              ast.MatMult: "@"}
"""Operators a str has no meaning for."""
_LITERALS = (ast.Tuple, ast.List, ast.Constant, ast.JoinedStr, ast.Dict, ast.Set)


def _operator_problem(node: ast.BinOp) -> str | None:
    """What ``'...' & (x,)`` raises: a str literal and a literal display joined by an operator
    neither has (``%`` was meant, usually)."""
    symbol = _OPERATORS.get(type(node.op))
    if symbol is None or not isinstance(node.right, _LITERALS):
        return None
    return (f"a str and a literal have no `{symbol}`: Python raises TypeError (`%` formats a "
            "string)")


def _bracketed_key(template: str, start: int) -> re.Match[str] | None:
    """The conversion at ``start`` whose key holds brackets of its own (``%(a(b))s``), read
    as Python does: the key ends at the bracket that closes the first."""
    depth, at = 0, start + 1
    for at in range(start + 1, len(template)):
        depth += {"(": 1, ")": -1}.get(template[at], 0)
        if depth == 0:
            break
    if depth:
        return None
    rest = PERCENT.match("%" + template[at + 1:])
    return rest if rest is not None and rest["key"] is None else None


def _hit(path: str, node: ast.AST, problem: str) -> Hit:
    return Hit(Span(path, node.lineno, node.col_offset + 1),  # type: ignore[attr-defined]
               f"`{shortened(ast.unparse(node))}`: {problem}")
