"""PYC015: a console script creates a node or spins, and nothing calls `rclpy.init()`."""

from __future__ import annotations

import ast
import builtins
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rosdistro import any_stdlib_module
from pkgtool.model.ast_nodes import descendants, nodes_of_class, subtree
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.imports import entry_points_installed
from pkgtool.rules.node_api import INITS, NODE_CLASSES, node_subclasses
from pkgtool.rules.syntax_trees import FUNCTIONS, Index, installed_trees
from pkgtool.rules.registry import rule

_SPINS = frozenset({"spin", "spin_once", "spin_until_future_complete"})
_DYNAMIC = frozenset({"exec", "eval", "__import__", "importlib", "runpy"})
"""Calls that run code pkgtool cannot see."""


def _initialises(tree: ast.Module, index: Index) -> bool:
    """True when the module may call ``rclpy.init``: any ``.init`` read, any name for it."""
    return any(n.attr == "init" for n in nodes_of_class(tree, ast.Attribute)) or \
        any(target in INITS for target in index.aliases.values()) or \
        any(i.module and i.module.split(".")[0] == "rclpy" and
            any(a.name == "init" for a in i.names) for i in index.import_froms)


def _root(func: ast.expr) -> ast.expr:
    while isinstance(func, ast.Attribute):
        func = func.value
    return func


class _Reach:
    """Walks an entry function and the module functions it calls, collecting node creations
    and spins, and noting calls that leave the module (``unknown``)."""

    def __init__(self, tree: ast.Module, index: Index) -> None:
        self.index = index
        self.functions = {s.name: s for s in tree.body if isinstance(s, FUNCTIONS)}
        self.nodes = {c.name for c in node_subclasses(index)}
        self.classes = {s.name for s in tree.body if isinstance(s, ast.ClassDef)}
        self.seen: set[str] = set()
        self.starts: list[ast.Call] = []
        self.unknown = False

    def visit(self, function: ast.FunctionDef | ast.AsyncFunctionDef) -> None:
        """Look at every call in ``function`` (nested code included)."""
        self.seen.add(function.name)
        nodes = subtree(function)
        local = {n.id for n in nodes if isinstance(n, ast.Name) and
                 not isinstance(n.ctx, ast.Load)}
        local |= {a.arg for a in descendants(function.args) if isinstance(a, ast.arg)}
        for node in nodes:
            if isinstance(node, (ast.Import, ast.ImportFrom)):
                self.unknown = True  # a local import: what it brings is not followed
            elif isinstance(node, ast.Call):
                self._call(node, local)

    def _call(self, call: ast.Call, local: set[str]) -> None:
        name = self.index.qualified(call.func)
        root = _root(call.func)
        attr = call.func.attr if isinstance(call.func, ast.Attribute) else ""
        if name in NODE_CLASSES or name and name.startswith("rclpy.") and attr in _SPINS or \
                isinstance(call.func, ast.Name) and call.func.id in self.nodes or \
                attr in _SPINS and isinstance(root, ast.Name) and root.id in local:
            self.starts.append(call)
        if name is not None:
            top = name.split(".")[0]
            self.unknown |= top != "rclpy" and (top not in any_stdlib_module() or
                                                top in _DYNAMIC)
        elif isinstance(root, ast.Name) and root.id not in local:
            self._global(root.id)

    def _global(self, name: str) -> None:
        if name in self.functions:
            if name not in self.seen:
                self.visit(self.functions[name])
        elif name in self.classes:
            return
        elif name in self.index.aliases or not hasattr(builtins, name) or name in _DYNAMIC:
            self.unknown = True


@rule("PYC015", "rclpy-not-initialised", Severity.ERROR,
      fix="Call `rclpy.init(args=args)` first in the entry function")
def rclpy_not_initialised(package: Package) -> Iterator[Hit]:
    """A console script creates a node or spins, but nothing calls `rclpy.init()`.

    ## What it does
    Follows each console script (`module:function` in setup.py) into its function, and the
    functions of the same module it calls. Reports the first node it creates (a `Node`
    subclass of the module, `Node(...)`, `rclpy.create_node`) or spin (`rclpy.spin*`, an
    executor's `spin*`) when the module never names `rclpy.init` (called, imported,
    `rclpy.utilities.init`, or `with rclpy.init():`). Functions that call code of other modules
    (other than rclpy and the standard library), import inside, or run dynamic code are not
    reported: that code may initialise rclpy.

    ## Why is this bad?
    The package builds, but the command dies at once with `rclpy._rclpy_pybind11.
    NotInitializedException: rclpy.init() has not been called. msg:cannot create node`.

    ## Example
    ```python
    def main():
        node = Talker()
        rclpy.spin(node)
    ```

    ## Use instead
    ```python
    def main(args=None):
        rclpy.init(args=args)
        node = Talker()
        rclpy.spin(node)
    ```
    """
    trees = {module.path: (tree, index) for module, tree, index in installed_trees(package)}
    for entry, path in entry_points_installed(package, "console_scripts"):
        tree, index = trees.get(path, (None, None))
        if tree is None or index is None or not entry.valid or _initialises(tree, index):
            continue
        function = next((s for s in tree.body if isinstance(s, FUNCTIONS) and
                         s.name == entry.attr), None)
        if function is None:
            continue
        reach = _Reach(tree, index)
        reach.visit(function)
        if reach.starts and not reach.unknown:
            start = min(reach.starts, key=lambda c: (
                not function.lineno <= c.lineno <= (function.end_lineno or 0), c.lineno,
                c.col_offset))
            yield Hit(Span(path, start.lineno, start.col_offset + 1),
                      f"`{entry.name}` runs `{entry.attr}()`, which reaches "
                      f"`{ast.unparse(start.func)}()` but nothing calls `rclpy.init()` first")
