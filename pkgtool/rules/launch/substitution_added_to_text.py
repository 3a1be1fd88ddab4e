"""LCH011: a launch substitution joined to text with ``+`` (``namespace + "/camera"``)."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import last_name
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.launch._python_launch import (first_substitution, launch_function_nodes,
                                                 substitution_made)
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index


def _text(value: ast.expr) -> bool:
    return isinstance(value, ast.JoinedStr) or \
        isinstance(value, ast.Constant) and isinstance(value.value, str)


@rule("LCH011", "substitution-added-to-text", Severity.ERROR,
      fix="Put the parts in a list: `[LaunchConfiguration('ns'), '/camera']`")
def substitution_added_to_text(package: Package) -> Iterator[Hit]:
    """A launch substitution is joined to a string with `+`.

    ## What it does
    In the functions of Python launch files, reports `+` between a string literal (or an
    f-string) and a substitution of `launch.substitutions` or `launch_ros.substitutions`:
    a call such as `LaunchConfiguration('ns')`, or a name the function binds once, to one;
    also such a substitution given to `os.path.join` or formatted into an f-string.

    ## Why is this bad?
    A substitution is not a string: it is only evaluated when the launch runs, and it
    defines no `+`. `ros2 launch` fails while it builds the description, with `TypeError:
    unsupported operand type(s) for +` (`os.path.join` raises TypeError the same way, and an
    f-string silently writes the object's repr, `<...FindPackageShare object at 0x...>`).
    Launch takes a list of parts instead (text and substitutions), concatenated when the
    launch runs.

    ## Example
    ```python
    namespace = LaunchConfiguration('namespace')
    Node(..., namespace=namespace + '/camera')
    ```

    ## Use instead
    ```python
    namespace = LaunchConfiguration('namespace')
    Node(..., namespace=[namespace, '/camera'])
    ```
    """
    for path, index, single, node in launch_function_nodes(package):
        if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
            pair = (node.left, node.right)
            made = first_substitution(pair, index, single)
            if made and any(_text(v) for v in pair):
                yield Hit(Span(path, node.lineno, node.col_offset + 1),
                          f"A `{made}` is joined to a string with `+`: it raises TypeError (a "
                          "substitution is no string)")
        else:
            yield from _joined_otherwise(path, node, index, single)


_SHOWN = frozenset({"print", "debug", "info", "warning", "warn", "error", "critical",
                    "exception"})
"""Calls that only show text (``print``, a Python logger's methods): no launch value."""


def _only_shown(node: ast.FormattedValue, index: Index) -> bool:
    """True when the f-string holding ``node`` is an argument of :data:`_SHOWN` (a debug
    ``print(f'ns: {ns}')`` while the description is built), not of a launch action."""
    string = index.parents.get(id(node))
    call = index.parents.get(id(string))
    return isinstance(call, ast.Call) and string in call.args and last_name(call.func) in _SHOWN


def _joined_otherwise(path: str, node: ast.AST, index: Index, single: dict[str, ast.expr]
                      ) -> Iterator[Hit]:
    """A hit when ``node`` gives a substitution to ``os.path.join`` (TypeError) or formats one
    into an f-string (the object's repr, not its value)."""
    if isinstance(node, ast.Call) and index.qualified(node.func) == "os.path.join":
        made = first_substitution(node.args, index, single)
        if made:
            yield Hit(Span(path, node.lineno, node.col_offset + 1),
                      f"A `{made}` is given to `os.path.join`: it raises TypeError (a "
                      "substitution is no path)",
                      "Use `PathJoinSubstitution([...])` with the same parts")
    elif isinstance(node, ast.FormattedValue) and not _only_shown(node, index):
        made = substitution_made(node.value, index, single)
        if made:
            yield Hit(Span(path, node.value.lineno, node.value.col_offset + 1),
                      f"A `{made}` is formatted into an f-string: the text is the object's "
                      f"repr (`<{made} object at 0x...>`), not the value launch gives it")
