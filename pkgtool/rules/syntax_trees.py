"""What the PYC rules share: parsed installed modules, indexed once, and static name resolution.

Names are resolved only when every binding of the name in the module is the same import
(``import numpy as np`` everywhere ``np`` is bound); a name also assigned, passed as a
parameter or defined is never resolved, so rules keyed on it stay silent.
"""

from __future__ import annotations

import ast
import posixpath
from collections.abc import Iterator

from pkgtool.model.ast_nodes import walk_once
from pkgtool.model.installed import installed_data, is_ament_python
from pkgtool.model.launch import kept_aside
from pkgtool.model.memo import per_package, per_tree
from pkgtool.model.modules import PythonModule
from pkgtool.model.package import Package
from pkgtool.model.python_visitor import parse_tree
from pkgtool.records import field, record
from pkgtool.rules.imports import installed_code, is_ros1_module

FUNCTIONS = (ast.FunctionDef, ast.AsyncFunctionDef)
_STOPS = (*FUNCTIONS, ast.ClassDef)
_LAMBDA_STOPS = (*_STOPS, ast.Lambda)


@record
class Index:
    """The nodes of one module the PYC rules look at, collected in a single walk.

    ``aliases`` maps names bound only by imports to the dotted name they stand for;
    ``relative`` holds the names bound only by relative imports (``from . import tools``);
    ``parents`` maps ``id(node)`` to the node's parent; ``bound`` holds every name the module
    binds anywhere (imports, assignments, parameters, definitions); ``dotted`` keeps what
    :meth:`qualified` found, by ``id(node)`` (with the node: its id is not reused meanwhile);
    ``around`` what :meth:`enclosing_function` found, the same way (rules ask about the same
    names).
    """

    attributes: list[ast.Attribute] = field(default_factory=list)
    calls: list[ast.Call] = field(default_factory=list)
    import_froms: list[ast.ImportFrom] = field(default_factory=list)
    tries: list[ast.Try] = field(default_factory=list)
    functions: list[ast.FunctionDef | ast.AsyncFunctionDef] = field(default_factory=list)
    classes: list[ast.ClassDef] = field(default_factory=list)
    parents: dict[int, ast.AST] = field(default_factory=dict)
    aliases: dict[str, str] = field(default_factory=dict)
    relative: frozenset[str] = frozenset()
    bound: frozenset[str] = frozenset()
    dotted: dict[int, tuple[ast.expr, str | None]] = field(default_factory=dict, compare=False,
                                                           repr=False)
    around: dict[tuple[int, bool], tuple[ast.AST, ast.AST | None]] = field(
        default_factory=dict, compare=False, repr=False)

    def defines_function(self, name: str) -> bool:
        """True when the module defines a function or method called ``name`` anywhere."""
        return name in _function_names(self)

    def imports_from(self, package: str) -> bool:
        """True when the module imports anything of the top-level ``package``."""
        return any(target.split(".")[0] == package for target in self.aliases.values())

    def qualified(self, node: ast.expr) -> str | None:
        """The dotted name an expression like ``np.int0`` stands for, or None; worked out once
        per node (rules ask about the same callees)."""
        known = self.dotted.get(id(node))
        if known is not None and known[0] is node:
            return known[1]
        found = _qualified(node, self.aliases)
        self.dotted[id(node)] = (node, found)
        return found

    def inside(self, node: ast.AST, parts: set[int]) -> bool:
        """True when ``node`` or a node around it is one of ``parts`` (ids of nodes)."""
        current: ast.AST | None = node
        while current is not None and id(current) not in parts:
            current = self.parents.get(id(current))
        return current is not None

    def module_of(self, node: ast.AST) -> ast.AST:
        """The module ``node`` is in (the top of its parents)."""
        while (parent := self.parents.get(id(node))) is not None:
            node = parent
        return node

    def enclosing_class(self, node: ast.AST) -> ast.ClassDef | None:
        """The innermost class around ``node``, or None."""
        parent = self.parents.get(id(node))
        while parent is not None and not isinstance(parent, ast.ClassDef):
            parent = self.parents.get(id(parent))
        return parent

    def annotation_holder(self, node: ast.AST) -> ast.AST | None:
        """The annotated assignment, parameter or function (its return) whose annotation
        ``node`` is in, or None."""
        child, parent = node, self.parents.get(id(node))
        while parent is not None:
            if isinstance(parent, (ast.AnnAssign, ast.arg)) and parent.annotation is child or \
                    isinstance(parent, FUNCTIONS) and parent.returns is child:
                return parent
            child, parent = parent, self.parents.get(id(parent))
        return None

    def in_unevaluated_annotation(self, node: ast.AST) -> bool:
        """True when ``node`` is inside an annotation Python never evaluates: that of an
        assignment in a function body (PEP 526), or any under ``from __future__ import
        annotations`` (PEP 563)."""
        holder = self.annotation_holder(node)
        if holder is None:
            return False
        postponed = any(i.module == "__future__" and any(a.name == "annotations" for a in i.names)
                        for i in self.import_froms)
        if isinstance(holder, ast.AnnAssign):
            return postponed or self.enclosing_function(holder) is not None
        return postponed

    def enclosing_function(self, node: ast.AST, *, through_lambdas: bool = True
                           ) -> ast.FunctionDef | ast.AsyncFunctionDef | None:
        """The innermost function around ``node`` (None at module or class level; also None
        inside a lambda, whose parameters may shadow the function's names, unless
        ``through_lambdas``)."""
        key = (id(node), through_lambdas)
        known = self.around.get(key)
        if known is not None and known[0] is node:
            return known[1]  # type: ignore[return-value]
        stops = _STOPS if through_lambdas else _LAMBDA_STOPS
        parent = self.parents.get(id(node))
        while parent is not None and not isinstance(parent, stops):
            parent = self.parents.get(id(parent))
        found = parent if isinstance(parent, FUNCTIONS) else None
        self.around[key] = (node, found)
        return found

    def functions_around(self, node: ast.AST) -> list[ast.FunctionDef | ast.AsyncFunctionDef]:
        """The functions around ``node``, innermost first, up to its class or the module."""
        found = []
        function = self.enclosing_function(node)
        while function is not None:
            found.append(function)
            function = self.enclosing_function(function)
        return found


@per_tree
def _function_names(index: Index) -> frozenset[str]:
    return frozenset(function.name for function in index.functions)


_RELATIVE = ""
"""The target :func:`_bindings` gives a name a relative import binds (its module is the
package's, known only with the package's layout)."""


def _bindings(node: ast.AST) -> Iterator[tuple[str, str | None]]:
    """The names ``node`` binds, each with the dotted import it stands for (None: not one;
    :data:`_RELATIVE`: a relative import)."""
    if isinstance(node, ast.Import):
        for alias in node.names:
            top = alias.name.split(".")[0]
            yield alias.asname or top, alias.name if alias.asname else top
    elif isinstance(node, ast.ImportFrom):
        for alias in node.names:
            target = f"{node.module}.{alias.name}" if node.level == 0 and node.module else \
                _RELATIVE if node.level else None
            yield alias.asname or alias.name, target
    elif isinstance(node, ast.Name) and not isinstance(node.ctx, ast.Load):
        yield node.id, None
    elif isinstance(node, ast.arg):
        yield node.arg, None
    elif isinstance(node, (*FUNCTIONS, ast.ClassDef)):
        yield node.name, None
    elif isinstance(node, (ast.ExceptHandler, ast.MatchAs, ast.MatchStar)) and node.name:
        yield node.name, None


_BINDERS = (ast.Import, ast.ImportFrom, ast.arg, *FUNCTIONS, ast.ClassDef, ast.ExceptHandler,
            ast.MatchAs, ast.MatchStar)
"""Nodes that bind names besides stored ``Name``s (those are tested directly: most nodes)."""
_COLLECTED = ((ast.Call, "calls"), (ast.ImportFrom, "import_froms"), (ast.Try, "tries"),
              (ast.FunctionDef, "functions"), (ast.AsyncFunctionDef, "functions"),
              (ast.ClassDef, "classes"))


def _index(tree: ast.Module) -> Index:
    """The index of ``tree``, from the nodes of the few classes it needs (the tree's one walk
    groups them): each list in walk order, ``functions`` the sync ones first."""
    walk = walk_once(tree)
    by_class = walk.by_class
    bound: dict[str, set[str | None]] = {}
    for name in by_class.get(ast.Name, ()):
        if not isinstance(name.ctx, ast.Load):  # type: ignore[attr-defined]
            bound.setdefault(name.id, set()).add(None)  # type: ignore[attr-defined]
    for kind in _BINDERS:
        for node in by_class.get(kind, ()):
            for name, target in _bindings(node):
                bound.setdefault(name, set()).add(target)
    index = Index(parents=walk.parents, bound=frozenset(bound),
                  relative=frozenset(name for name, targets in bound.items()
                                     if targets == {_RELATIVE} and name != "*"))
    index.attributes.extend(node for node in by_class.get(ast.Attribute, ())  # type: ignore
                            if isinstance(node.ctx, ast.Load))  # type: ignore[attr-defined]
    for kind, field_name in _COLLECTED:
        getattr(index, field_name).extend(by_class.get(kind, ()))
    index.aliases.update({name: target for name, (target, *more) in bound.items()
                          if not more and target and name != "*"})
    return index


index_of = per_tree(_index)
"""The :class:`Index` of a tree, built on first use (only rules that need one pay for it)."""


@per_package
def installed_modules(package: Package) -> tuple[tuple[PythonModule, ast.Module], ...]:
    """Installed, parseable modules with their syntax trees (the model's parse, shared), listed
    once per package (most PYC rules ask); not ROS 1 modules (:func:`is_ros1_module`)."""
    return tuple(_installed_modules(package))


def _installed_modules(package: Package) -> Iterator[tuple[PythonModule, ast.Module]]:
    for module in installed_code(package):
        if is_ros1_module(package, module) or _unreachable_copy(package, module):
            continue  # ROS 1 code left in a ROS 2 package: rospy's API, not rclpy's
        text = package.texts.get(module.path)
        tree = parse_tree(module.path, text) if text is not None and not module.syntax_error \
            else None
        if isinstance(tree, ast.Module):
            yield module, tree


def _unreachable_copy(package: Package, module: PythonModule) -> bool:
    """True for a copy kept aside under a name no import can spell (``hover copy.py``,
    ``node (old).py``) that is not installed as a program either: nothing ever runs it."""
    stem = posixpath.basename(module.path)[:-3]
    if stem.isidentifier() or not kept_aside(module.path) or not is_ament_python(package):
        return False
    data = installed_data(package)
    scripts = package.setup_py.scripts if package.setup_py else None
    programs = {source for target, source in (data or {}).items()
                if target.startswith(f"lib/{package.name}/")}
    return data is not None and module.path not in programs and \
        module.path not in {posixpath.normpath(script) for script in scripts or ()}


@per_package
def installed_trees(package: Package) -> tuple[tuple[PythonModule, ast.Module, Index], ...]:
    """Installed, parseable modules with their syntax trees and indexes, once per package."""
    return tuple((module, tree, index_of(tree)) for module, tree in installed_modules(package))


@per_package
def installed_tree_of(package: Package) -> dict[int, ast.Module]:
    """The syntax tree of each installed module by ``id`` of its index (a rule holding an
    index from :func:`installed_trees` or :func:`~pkgtool.rules.node_api.node_api_calls`)."""
    return {id(index): tree for _, tree, index in installed_trees(package)}


@per_package
def base_names(package: Package) -> frozenset[str]:
    """The names the classes of the installed modules derive from (``Base`` of ``class
    A(Base)``, ``Node`` of ``class A(rclpy.node.Node)``)."""
    return frozenset(name for _, _, index in installed_trees(package) for cls in index.classes
                     for base in cls.bases if (name := base_name(base)) is not None)


@per_package
def _overrides(package: Package) -> frozenset[tuple[str, str]]:
    """(base class name, method name) for each method a class of the installed modules
    defines, by each name its bases are written with."""
    return frozenset((name, statement.name) for _, _, index in installed_trees(package)
                     for cls in index.classes for base in cls.bases
                     if (name := base_name(base)) is not None
                     for statement in cls.body if isinstance(statement, FUNCTIONS))


def overridden(package: Package, method: ast.AST, index: Index) -> bool:
    """True when ``method`` is a method that a class deriving from its class (by name)
    defines again: on such an instance, ``self.method`` runs the other one."""
    cls = index.parents.get(id(method))
    return isinstance(cls, ast.ClassDef) and isinstance(method, FUNCTIONS) and \
        (cls.name, method.name) in _overrides(package)


def base_name(base: ast.expr) -> str | None:
    """The name a base class is written with (``Base``, ``Node`` of ``rclpy.node.Node``), or
    None for any other expression."""
    return base.id if isinstance(base, ast.Name) else \
        base.attr if isinstance(base, ast.Attribute) else None


def python_files(package: Package, containing: tuple[str, ...] = ()
                 ) -> Iterator[tuple[str, str, ast.Module]]:
    """(path, text, tree) of every Python file of the package that parses (setup.py, modules,
    launch files, tests), in path order; with ``containing``, only the files whose text holds
    one of those strings (the others cannot match: spared the walk)."""
    for path, text in sorted(package.texts.items()):
        if path.endswith(".py") and (not containing or any(s in text for s in containing)):
            tree = parse_tree(path, text)
            if isinstance(tree, ast.Module):
                yield path, text, tree


def _qualified(node: ast.expr, aliases: dict[str, str]) -> str | None:
    """The dotted name an expression like ``np.int0`` stands for, or None."""
    attrs: list[str] = []
    while isinstance(node, ast.Attribute):
        attrs.append(node.attr)
        node = node.value
    if not isinstance(node, ast.Name) or node.id not in aliases:
        return None
    return ".".join([aliases[node.id], *reversed(attrs)])


@per_tree
def resolved_attributes(index: Index) -> tuple[tuple[ast.Attribute, str, str], ...]:
    """Attribute reads whose base resolves: the node, the owner's dotted name, the attribute
    (worked out once per index: PYC002 and PYC004 read the same)."""
    return tuple(_resolved(index))


def _resolved(index: Index) -> Iterator[tuple[ast.Attribute, str, str]]:
    for node in index.attributes:
        name = index.qualified(node)
        if name is not None:
            owner, _, attr = name.rpartition(".")
            yield node, owner, attr


def python_launch_files(package: Package) -> Iterator[tuple[str, PythonModule, str]]:
    """(path, module, text) of each Python launch file that parses and is not a test."""
    for launch in package.launch_files:
        module = launch.python
        text = package.texts.get(launch.path)
        if module is not None and not module.syntax_error and text is not None and \
                not module.is_test:
            yield launch.path, module, text


def launch_trees(package: Package) -> Iterator[tuple[str, ast.Module, Index]]:
    """(path, syntax tree, index) of each file :func:`python_launch_files` gives."""
    for path, _, text in python_launch_files(package):
        tree = parse_tree(path, text)
        if isinstance(tree, ast.Module):
            yield path, tree, index_of(tree)


def launch_indexes(package: Package) -> Iterator[tuple[str, Index]]:
    """(path, index of its syntax tree) of each file :func:`python_launch_files` gives."""
    for path, _, index in launch_trees(package):
        yield path, index
