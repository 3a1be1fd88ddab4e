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
from pkgtool.model.ast_nodes import enclosing, nodes_of_class, walk_once
from pkgtool.model.memo import per_package
from pkgtool.model.package import Package
from pkgtool.model.python_visitor import parse_tree
from pkgtool.records import record
from pkgtool.rules.syntax_trees import Index, installed_trees

_WORD = lazy_pattern(r"[A-Za-z_]\w*")


def never_called(package: Package, node: ast.AST, index: Index) -> bool:
    """True when ``node`` is inside a method that nothing in the package names (see the
    module's docstring)."""
    return _in_uncalled_method(package, index.enclosing_function(node), index)


def _in_uncalled_method(package: Package, function: ast.AST | None, index: Index) -> bool:
    """True when ``function``, or a function around it, is a method nothing names."""
    while isinstance(function, (ast.FunctionDef, ast.AsyncFunctionDef)):
        owner = index.parents.get(id(function))
        if isinstance(owner, ast.ClassDef):
            names = _named(package)
            known = names.of(_paths(package).get(id(index), ""), owner.name)
            return not function.decorator_list and not function.name.startswith("__") and \
                function.name not in LIFECYCLE_NODE_ATTRIBUTES and \
                all((index.qualified(base) or "").startswith("rclpy.") for base in owner.bases) \
                and not names.everything and function.name not in known and \
                not any(is_typo(function.name, name) for name in known)
        function = index.enclosing_function(function)
    return False


@per_package
def _paths(package: Package) -> dict[int, str]:
    """The path of each installed module by the id of its index."""
    return {id(index): module.path for module, _, index in installed_trees(package)}


@record
class _Names:
    """What the package's code names: ``anywhere`` (names, attributes not read on ``self``,
    imported names, the words of its strings but docstrings, and of its setup.cfg), the
    attributes read on ``self`` in each class's methods, and each class's bases (by name);
    ``everything`` when a method may be named at run time (``getattr`` with a computed
    name)."""

    anywhere: frozenset[str]
    on_self: dict[tuple[str, str], set[str]]
    bases: dict[tuple[str, str], set[str]]
    """Both by (module path, class name): copies of a module may hold classes of one name."""
    everything: bool = False

    def of(self, path: str, cls: str) -> set[str]:
        """The names that may call a method of the class ``cls`` of the module ``path``:
        those named anywhere, and those read on ``self`` in it, in its bases or in the classes
        deriving from it (these two by name, in any module)."""
        kin = self.bases.get((path, cls), set()) | \
            {other for (_, other), bases in self.bases.items() if cls in bases}
        return set(self.anywhere).union(
            self.on_self.get((path, cls), ()),
            *(names for (_, other), names in self.on_self.items() if other in kin))


@per_package
def _named(package: Package) -> _Names:
    """What the package's code names (:class:`_Names`)."""
    found: set[str] = set(_WORD.findall(package.texts.get("setup.cfg", "")))
    on_self: dict[tuple[str, str], set[str]] = {}
    bases: dict[tuple[str, str], set[str]] = {}
    for path, text in package.texts.items():
        tree = parse_tree(path, text) if path.endswith(".py") else None
        if not isinstance(tree, ast.Module):
            continue
        if any(isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and
               node.func.id == "getattr" and len(node.args) > 1 and
               not isinstance(node.args[1], ast.Constant)
               for node in nodes_of_class(tree, ast.Call)):
            return _Names(frozenset(), {}, {}, everything=True)  # getattr(self, f'on_{x}')
        docstrings = {id(node.value) for node in nodes_of_class(tree, ast.Expr)
                      if isinstance(node, ast.Expr) and isinstance(node.value, ast.Constant)}
        parents = walk_once(tree).parents
        for cls in nodes_of_class(tree, ast.ClassDef):
            assert isinstance(cls, ast.ClassDef)
            bases.setdefault((path, cls.name), set()).update(
                ast.unparse(base).rpartition(".")[2] for base in cls.bases)
        for node in nodes_of_class(tree, ast.Name, ast.Attribute, ast.Constant, ast.alias):
            if id(node) in docstrings:
                continue
            if isinstance(node, ast.Name):
                found.add(node.id)
            elif isinstance(node, ast.Attribute):
                owner = enclosing(node, parents, (ast.ClassDef,)) \
                    if isinstance(node.value, ast.Name) and node.value.id == "self" else None
                if isinstance(owner, ast.ClassDef):
                    on_self.setdefault((path, owner.name), set()).add(node.attr)
                else:
                    found.add(node.attr)
            elif isinstance(node, ast.alias):
                found.add(node.asname or node.name)
            elif isinstance(node, ast.Constant) and isinstance(node.value, str):
                found.update(_WORD.findall(node.value))
    return _Names(frozenset(found), on_self, bases)
