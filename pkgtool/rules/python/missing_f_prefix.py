"""PYC058: a logged or printed string holds ``{name}`` fields but lacks its ``f`` prefix."""

from __future__ import annotations

import ast
import string
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._loggers import LEVELS, logged_message, logger_method_calls
from pkgtool.rules.registry import rule
from pkgtool.rules.scopes import scope_bindings
from pkgtool.rules.syntax_trees import Index, installed_trees


def _fields(text: str) -> list[ast.expr] | None:
    """The expressions of the replacement fields of ``text`` read as an f-string's, or None
    when ``text`` is no f-string without its prefix: no field, a field that is empty or a
    number (a ``str.format`` template), one that is no expression or names nothing."""
    try:
        parsed = [field for _, field, _, _ in string.Formatter().parse(text) if field is not None]
        expressions = [ast.parse(field.strip(), mode="eval").body for field in parsed]
    except (ValueError, SyntaxError):
        return None
    if not expressions or any(not _names(e) for e in expressions):
        return None
    return expressions


def _names(expression: ast.expr) -> list[str]:
    """The names an expression reads."""
    return [n.id for n in ast.walk(expression) if isinstance(n, ast.Name)]


def _bound_around(node: ast.AST, tree: ast.Module, index: Index) -> set[str]:
    """The names bound where ``node`` is: in each function around it and in the module."""
    around = [scope_bindings(function) for function in index.functions_around(node)]
    return set(scope_bindings(tree)).union(*around)


def _messages(tree: ast.Module, index: Index, package: Package) -> Iterator[ast.Constant]:
    """The string literals given as the message of an rclpy logger's logging method, or as
    an argument of ``print()``."""
    for call, func in logger_method_calls(tree, index, package):
        message = logged_message(call) if func.attr in LEVELS else None
        if isinstance(message, ast.Constant):
            yield message
    if "print" in index.bound:
        return
    for call in index.calls:
        if isinstance(call.func, ast.Name) and call.func.id == "print":
            yield from (a for a in call.args if isinstance(a, ast.Constant))


@rule("PYC058", "missing-f-prefix", Severity.WARNING,
      fix="Add the `f` prefix: `f'Count: {count}'`")
def missing_f_prefix(package: Package) -> Iterator[Hit]:
    """A logged or printed string has `{name}` fields but no `f` prefix.

    ## What it does
    Reports a string literal given as the message of an rclpy logger's logging method
    (`self.get_logger().info('...')`, and loggers kept in a name or attribute) or to
    `print()`, with no `f` prefix, whose every `{...}` field is a Python expression reading
    names bound where the string is (`{count}`, `{self.count}`, `{msg.data:.2f}`): an
    f-string without its `f`. Strings with an empty or numbered field (`{}`, `{0}`: a
    `str.format` template), a field naming nothing bound there, or text that is no
    expression (`{"a": 1}` is JSON) are left alone; so are strings formatted in place
    (`'{x}'.format(x=1)` is a call, not the message).

    ## Why is this bad?
    Without the prefix Python does not format the string: the log shows
    `Published message {self.count}` instead of the count, and nothing fails to tell.

    ## Example
    ```python
    self.get_logger().info('Received {msg.data}')
    ```

    ## Use instead
    ```python
    self.get_logger().info(f'Received {msg.data}')
    ```
    """
    for module, tree, index in installed_trees(package):
        for message in _messages(tree, index, package):
            if not isinstance(message.value, str) or "{" not in message.value:
                continue
            fields = _fields(message.value)
            if fields is None:
                continue
            bound = _bound_around(message, tree, index)
            if all(name in bound for field in fields for name in _names(field)):
                shown = ", ".join(f"`{{{ast.unparse(f)}}}`" for f in fields[:3])
                yield Hit(Span(module.path, message.lineno, message.col_offset + 1),
                          f"The string has the field{'s' if len(fields) > 1 else ''} {shown} "
                          "but no `f` prefix: it is shown as written, braces and all, not "
                          "formatted")
