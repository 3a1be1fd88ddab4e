"""Methods nothing in the package ever names: what they read never runs (PYC023, PYC064).

A method of a class whose bases are rclpy's classes alone (or none) runs only when something
names it: a call, a bound method handed to a timer or a subscription, ``getattr`` with its
name, an entry point. One whose name appears nowhere in the package's Python code (nor in its
setup.cfg), nor with a typo (``self.timer_calback`` handed to a timer means
``timer_callback``), that overrides nothing of rclpy's nodes and carries no decorator, is dead
code (copied in, or its only caller commented out): an attribute it reads that nothing sets is
a mistake that cannot happen. A package that calls ``getattr`` with a computed name
(``getattr(self, f'state_{state}')()``) may call any method: none is said never to run.
"""

from __future__ import annotations

import ast

from pkgtool.knowledge.rclpy_node import LIFECYCLE_NODE_ATTRIBUTES
from pkgtool.knowledge.rosdistro import is_typo
from pkgtool.lazy_regex import lazy_pattern
from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.model.memo import per_package
from pkgtool.model.package import Package
from pkgtool.model.python_visitor import parse_tree
from pkgtool.rules.syntax_trees import Index

_WORD = lazy_pattern(r"[A-Za-z_]\w*")
ANY_NAME = "*"
"""What :func:`_named` holds when the package calls methods by computed names."""


def never_called(package: Package, node: ast.AST, index: Index) -> bool:
    """True when ``node`` is inside a method that nothing in the package names (see the
    module's docstring)."""
    return _in_uncalled_method(package, index.enclosing_function(node), index)


def _in_uncalled_method(package: Package, function: ast.AST | None, index: Index) -> bool:
    """True when ``function``, or a function around it, is a method nothing names."""
    while isinstance(function, (ast.FunctionDef, ast.AsyncFunctionDef)):
        owner = index.parents.get(id(function))
        if isinstance(owner, ast.ClassDef):
            return not function.decorator_list and not function.name.startswith("__") and \
                function.name not in LIFECYCLE_NODE_ATTRIBUTES and \
                all((index.qualified(base) or "").startswith("rclpy.") for base in owner.bases) \
                and function.name not in _named(package) and ANY_NAME not in _named(package) \
                and not any(is_typo(function.name, name) for name in _named(package))
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
        if any(isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and
               node.func.id == "getattr" and len(node.args) > 1 and
               not isinstance(node.args[1], ast.Constant)
               for node in nodes_of_class(tree, ast.Call)):
            return frozenset({ANY_NAME})  # getattr(self, f'state_{x}'): any method may run
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
