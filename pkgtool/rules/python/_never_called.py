"""Methods nothing in the package ever names: what they read never runs (PYC023, PYC064).

A method of a class whose bases are rclpy's classes alone (or none) runs only when something
names it: a call, a bound method handed to a timer or a subscription, ``getattr`` with its
name, an entry point. One whose name appears nowhere in the package's Python code (nor in its
setup.cfg), nor with a typo (``self.timer_calback`` handed to a timer means
``timer_callback``), that overrides nothing of rclpy's nodes and carries no decorator, is dead
code (copied in, or its only caller commented out): an attribute it reads that nothing sets is
a mistake that cannot happen.
"""

from __future__ import annotations

import ast
from difflib import get_close_matches

from pkgtool.knowledge.rclpy_node import LIFECYCLE_NODE_ATTRIBUTES
from pkgtool.lazy_regex import lazy_pattern
from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.model.memo import per_package
from pkgtool.model.package import Package
from pkgtool.model.python_visitor import parse_tree
from pkgtool.rules.syntax_trees import Index

_WORD = lazy_pattern(r"[A-Za-z_]\w*")


def never_called(package: Package, node: ast.AST, index: Index) -> bool:
    """True when ``node`` is inside a method that nothing in the package names (see the
    module's docstring)."""
    function = index.enclosing_function(node)
    while function is not None:
        owner = index.parents.get(id(function))
        if isinstance(owner, ast.ClassDef):
            return not function.decorator_list and not function.name.startswith("__") and \
                function.name not in LIFECYCLE_NODE_ATTRIBUTES and \
                all((index.qualified(base) or "").startswith("rclpy.") for base in owner.bases) \
                and function.name not in _named(package) and \
                not get_close_matches(function.name, _named(package), n=1, cutoff=0.85)
        function = index.enclosing_function(function)
    return False


@per_package
def _named(package: Package) -> frozenset[str]:
    """Every name the package's Python code reads or writes (names, attributes, imported
    names, the words of its strings but docstrings), and the words of its setup.cfg."""
    found: set[str] = set(_WORD.findall(package.texts.get("setup.cfg", "")))
    for path, text in package.texts.items():
        tree = parse_tree(path, text) if path.endswith(".py") else None
        if not isinstance(tree, ast.Module):
            continue
        docstrings = {id(node.value) for node in nodes_of_class(tree, ast.Expr)
                      if isinstance(node, ast.Expr) and isinstance(node.value, ast.Constant)}
        for node in nodes_of_class(tree, ast.Name, ast.Attribute, ast.Constant, ast.alias):
            if id(node) in docstrings:
                continue
            if isinstance(node, ast.Name):
                found.add(node.id)
            elif isinstance(node, ast.Attribute):
                found.add(node.attr)
            elif isinstance(node, ast.alias):
                found.add(node.asname or node.name)
            elif isinstance(node, ast.Constant) and isinstance(node.value, str):
                found.update(_WORD.findall(node.value))
    return frozenset(found)
