"""PYC081: ``except KeyboardInterrupt():``, a handler naming an exception instance, not a class."""

from __future__ import annotations

import ast
import builtins
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import index_of, python_files

BUILTIN_EXCEPTIONS = frozenset(name for name, value in vars(builtins).items()
                               if isinstance(value, type) and issubclass(value, BaseException))
"""The exception classes Python provides without an import (``KeyboardInterrupt``...)."""


def instances_caught(handler: ast.ExceptHandler, bound: frozenset[str]) -> list[ast.Call]:
    """The calls of a built-in exception class (not rebound by the module, ``bound``) that
    ``handler`` names as what it catches, alone or in a tuple."""
    kinds = handler.type.elts if isinstance(handler.type, ast.Tuple) else [handler.type]
    return [kind for kind in kinds if isinstance(kind, ast.Call) and
            isinstance(kind.func, ast.Name) and kind.func.id in BUILTIN_EXCEPTIONS and
            kind.func.id not in bound]


@rule("PYC081", "exception-instance-caught", Severity.ERROR,
      fix="Name the class: `except KeyboardInterrupt:`")
def exception_instance_caught(package: Package) -> Iterator[Hit]:
    """An `except` clause names an exception instance (`KeyboardInterrupt()`), not a class.

    ## What it does
    Reports `except KeyboardInterrupt():` and `except (ValueError(), KeyError):` in every
    Python file of the package: a call of one of Python's built-in exception classes where
    the handler names what it catches (a module that binds that name itself is left alone).

    ## Why is this bad?
    `except` takes classes. The handler is evaluated only when an exception reaches it, and
    then Python raises `TypeError: catching classes that do not inherit from BaseException is
    not allowed` instead of handling it: Ctrl+C crashes the node with a second traceback
    instead of shutting it down cleanly.

    ## Example
    ```python
    try:
        rclpy.spin(node)
    except KeyboardInterrupt():
        pass
    ```

    ## Use instead
    ```python
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    ```
    """
    for path, _, tree in python_files(package, ("except",)):
        bound = index_of(tree).bound
        for handler in nodes_of_class(tree, ast.ExceptHandler):
            for call in instances_caught(handler, bound):  # type: ignore[arg-type]
                name = call.func.id  # type: ignore[attr-defined]
                yield Hit(Span(path, call.lineno, call.col_offset + 1),
                          f"`except` names `{ast.unparse(call)}`, an instance of `{name}`, "
                          "not a class: when an exception reaches this handler, Python raises "
                          "TypeError instead of catching it", f"Write `{name}`")
