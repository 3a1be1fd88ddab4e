"""Fixer of Python code: a callback called where it should be passed loses its ``()``."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.edit.changes import read_source
from pkgtool.edit.core import Edit, EditError, Fix
from pkgtool.findings import Finding
from pkgtool.fix.registry import fixer
from pkgtool.model.package import Package


@fixer("PYC013", "Pass the callback without calling it")
def callback_called(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Delete the empty ``()`` after the callback PYC013 reports (``self.tick()`` becomes
    ``self.tick``). Safe: the called function returns None, so rclpy got None; calls with
    arguments are left to the user."""
    for path in sorted({f.span.path for f in findings}):
        try:
            source = read_source(package.root, path)
            tree = ast.parse(source.text) if source is not None else None
        except (EditError, SyntaxError, ValueError):
            continue
        if source is None or tree is None:
            continue
        places = {(f.span.line, f.span.col - 1) for f in findings if f.span.path == path}
        for node in ast.walk(tree):
            if isinstance(node, ast.Call) and (node.lineno, node.col_offset) in places and \
                    isinstance(node.func, (ast.Name, ast.Attribute)) and \
                    not node.args and not node.keywords and node.end_lineno is not None and \
                    node.func.end_lineno is not None and node.end_col_offset is not None:
                start = source.offset_of_utf8(node.func.end_lineno, node.func.end_col_offset or 0)
                end = source.offset_of_utf8(node.end_lineno, node.end_col_offset)
                name = ast.unparse(node.func)
                yield Fix(f"Pass `{name}` instead of `{name}()`", (Edit(path, start, end, ""),))
