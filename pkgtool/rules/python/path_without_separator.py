"""PYC032: a package's folder joined to a relative path with no ``/`` between them."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import nodes_of
from pkgtool.model.package import Package
from pkgtool.model.python_visitor import parse_tree
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule
from pkgtool.rules.scopes import single_assignments
from pkgtool.rules.syntax_trees import Index, index_of, installed_modules

_FOLDERS = frozenset(f"ament_index_python{module}.{function}"
                     for module in ("", ".packages")
                     for function in ("get_package_share_directory", "get_package_prefix"))
"""The functions that give a package's folder as a string with no trailing ``/``."""


def _folder(value: ast.expr, index: Index, scopes: tuple[dict[str, ast.expr], ...]) -> str | None:
    """The function of :data:`_FOLDERS` that ``value`` calls (directly, or through a name bound
    once, to such a call, in the function or else in the module), else None."""
    if isinstance(value, ast.Name):
        value = next((scope[value.id] for scope in scopes if value.id in scope), value)
    if isinstance(value, ast.Call):
        called = index.qualified(value.func)
        if called in _FOLDERS:
            return called.rpartition(".")[2]
    return None


def _relative(value: ast.expr) -> str | None:
    """The text a string literal or an f-string starts with, when that starts like a relative
    path (a letter, a digit or ``_``: not ``/``, nor the ``:`` of a path list or the space of a
    command line), else None."""
    if isinstance(value, ast.JoinedStr) and value.values:
        value = value.values[0]
    if isinstance(value, ast.Constant) and isinstance(value.value, str) and \
            value.value[:1].replace("_", "a").isalnum() and value.value[:1].isascii():
        return value.value
    return None


def joins(tree: ast.Module, index: Index) -> Iterator[tuple[ast.expr, ast.expr, str, str]]:
    """(node, left, function, text) of each ``folder + 'text'`` and ``f'{folder}text'``:
    ``left`` is the folder operand or the f-string's replacement field. None in a module
    that imports nothing of ``ament_index_python`` (no call can be one of :data:`_FOLDERS`)."""
    if not index.imports_from("ament_index_python"):
        return
    scopes: dict[int, tuple[dict[str, ast.expr], ...]] = {}  # by function, for candidates only
    for node in nodes_of(tree):
        if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
            pairs = [(node.left, node.right)]
        elif isinstance(node, ast.JoinedStr):
            pairs = [(a.value, b) for a, b in zip(node.values, node.values[1:])
                     if isinstance(a, ast.FormattedValue) and a.format_spec is None]
        else:
            continue
        for left, right in pairs:
            text = _relative(right) if isinstance(left, (ast.Name, ast.Call)) else None
            if text is None:
                continue
            function = index.enclosing_function(node)
            if id(tree) not in scopes:
                scopes[id(tree)] = (single_assignments(tree),)
            if function is not None and id(function) not in scopes:
                scopes[id(function)] = (single_assignments(function), *scopes[id(tree)])
            called = _folder(left, index, scopes[id(function or tree)])
            if called:
                yield node, left, called, text


@rule("PYC032", "path-without-separator", Severity.ERROR,
      fix="Join with `os.path.join(folder, 'config', 'params.yaml')`")
def path_without_separator(package: Package) -> Iterator[Hit]:
    """A package's folder is joined to a relative path with no `/` between them.

    ## What it does
    In installed code and Python launch files, reports `+` and f-strings that put a relative
    path (a string literal, or an f-string's text, starting with a letter, a digit or `_`)
    right after what `get_package_share_directory()` or `get_package_prefix()` of
    `ament_index_python` returns: the call itself, or a name bound once to it in the function
    or the module.

    ## Why is this bad?
    These functions return the folder without a trailing `/`, so
    `get_package_share_directory('my_pkg') + 'config/params.yaml'` is
    `.../share/my_pkgconfig/params.yaml`, a file that does not exist: the node or the launch
    fails to open it (or a parameter file is silently not found) on every machine.

    ## Example
    ```python
    share = get_package_share_directory('my_pkg')
    params = share + 'config/params.yaml'
    ```

    ## Use instead
    ```python
    share = get_package_share_directory('my_pkg')
    params = os.path.join(share, 'config', 'params.yaml')
    ```
    """
    trees = [(module.path, tree) for module, tree in installed_modules(package)]
    for path in (f.path for f in package.launch_files if f.kind == "python"):
        tree = parse_tree(path, package.texts[path]) if path in package.texts else None
        if isinstance(tree, ast.Module):
            trees.append((path, tree))
    for path, tree in trees:
        for node, _, called, text in joins(tree, index_of(tree)):
            yield Hit(Span(path, node.lineno, node.col_offset + 1),
                      f"`{called}()` is joined to `{text}` with no `/` between them: the path "
                      f"names `<folder>{text}`, not a file in the folder")
