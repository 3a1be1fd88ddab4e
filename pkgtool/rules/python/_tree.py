"""What the PYC rules share: parsed trees of installed modules and static name resolution.

Names are resolved only when every binding of the name in the module is the same import
(``import numpy as np`` everywhere ``np`` is bound); a name also assigned, passed as a
parameter or defined is never resolved, so rules keyed on it stay silent.
"""

from __future__ import annotations

import ast
from collections.abc import Iterator
from functools import lru_cache

from pkgtool.model.modules import PythonModule
from pkgtool.model.package import Package
from pkgtool.rules.dependencies._imports import installed_code


@lru_cache(maxsize=256)
def _parse(path: str, text: str) -> ast.Module | None:
    try:
        return ast.parse(text, filename=path)
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return None


def installed_trees(package: Package) -> Iterator[tuple[PythonModule, ast.Module]]:
    """Installed, parseable modules with their syntax trees."""
    for module in installed_code(package):
        text = package.texts.get(module.path)
        tree = _parse(module.path, text) if text is not None and not module.syntax_error else None
        if tree is not None:
            yield module, tree


def _bind(found: dict[str, set[str | None]], name: str, target: str | None) -> None:
    found.setdefault(name, set()).add(target)


@lru_cache(maxsize=256)
def import_aliases(tree: ast.Module) -> dict[str, str]:
    """Names bound only by imports, each to the one dotted name it stands for."""
    found: dict[str, set[str | None]] = {}
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            for alias in node.names:
                top = alias.name.split(".")[0]
                _bind(found, alias.asname or top, alias.name if alias.asname else top)
        elif isinstance(node, ast.ImportFrom):
            for alias in node.names:
                target = f"{node.module}.{alias.name}" if node.level == 0 and node.module else None
                _bind(found, alias.asname or alias.name, target)
        elif isinstance(node, ast.Name) and not isinstance(node.ctx, ast.Load):
            _bind(found, node.id, None)
        elif isinstance(node, ast.arg):
            _bind(found, node.arg, None)
        elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            _bind(found, node.name, None)
        elif isinstance(node, ast.ExceptHandler) and node.name:
            _bind(found, node.name, None)
        elif isinstance(node, (ast.MatchAs, ast.MatchStar)) and node.name:
            _bind(found, node.name, None)
    return {name: next(iter(targets)) for name, targets in found.items()  # type: ignore[misc]
            if len(targets) == 1 and None not in targets and name != "*"}


def qualified(node: ast.expr, aliases: dict[str, str]) -> str | None:
    """The dotted name an expression like ``np.int0`` stands for, or None."""
    attrs: list[str] = []
    while isinstance(node, ast.Attribute):
        attrs.append(node.attr)
        node = node.value
    if not isinstance(node, ast.Name) or node.id not in aliases:
        return None
    return ".".join([aliases[node.id], *reversed(attrs)])


def loaded_attributes(tree: ast.Module, aliases: dict[str, str]
                      ) -> Iterator[tuple[ast.Attribute, str]]:
    """Every attribute read whose base resolves, with its dotted name (outermost first)."""
    for node in ast.walk(tree):
        if isinstance(node, ast.Attribute) and isinstance(node.ctx, ast.Load):
            name = qualified(node, aliases)
            if name is not None:
                yield node, name
