"""PYC072: a class written as a node that derives from no class (``class Talker:`` missing
``(Node)``), instantiated by the package itself."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rclpy_node import NODE_ATTRIBUTES
from pkgtool.model.ast_nodes import is_super_init
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._attribute_guards import guarded, probed_names
from pkgtool.rules.python._value_types import attribute_stores, receiver_class
from pkgtool.rules.python._package_classes import (attributes_of_class, closed_class,
                                                   package_class, package_classes)
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, installed_trees


@rule("PYC072", "node-class-without-node-base", Severity.ERROR,
      fix="Derive the class from rclpy's Node: `class Talker(Node):`")
def node_class_without_node_base(package: Package) -> Iterator[Hit]:
    """A class the package instantiates uses rclpy's Node API on `self` but derives from no
    class.

    ## What it does
    Reports a class of the installed modules that derives from nothing (or `object` alone,
    or only package classes that do), which the package itself instantiates (`Talker()`),
    and that either passes arguments to `super().__init__(...)` in its `__init__`
    (`super().__init__('talker')`) or reads on `self` a method of rclpy's `Node`
    (`self.create_publisher`, `self.get_logger`, `self.declare_parameter`) that neither the
    class nor its bases define and that nothing in the package stores. The usual cause: the
    base was left out (`class Talker:` for `class Talker(Node):`). A class no call of the
    package instantiates may be a mixin meant to be combined with `Node`, and a class some
    package class derives from may be one too: both are left alone, as are classes with a
    metaclass, class decorators (other than `@dataclass`), `__getattr__`, and names the
    module probes with `hasattr`/`getattr` or reads inside a `try` that catches
    `AttributeError`.

    ## Why is this bad?
    The class's instances are plain objects: `super().__init__('talker')` calls
    `object.__init__`, which takes no arguments (TypeError), and `self.create_publisher(...)`
    raises AttributeError. The node fails the moment it is made.

    ## Example
    ```python
    class Talker:
        def __init__(self):
            super().__init__('talker')
            self.publisher = self.create_publisher(String, 'chatter', 10)
    ```

    ## Use instead
    ```python
    from rclpy.node import Node

    class Talker(Node):
        def __init__(self):
            super().__init__('talker')
            self.publisher = self.create_publisher(String, 'chatter', 10)
    ```
    """
    candidates = _instantiated_plain_classes(package)
    if not candidates:
        return
    stores = attribute_stores(package)
    for module, _, index in installed_trees(package):
        probed: frozenset[str] | None = None
        for cls in index.classes:
            dotted = candidates.get(id(cls))
            if dotted is None:
                continue
            probed = probed_names(index) if probed is None else probed
            reason = _super_init_arguments(cls) or \
                _node_method_read(cls, dotted, index, package, stores, probed)
            if reason is None:
                continue
            node, what = reason
            span = Span(module.path, node.lineno, node.col_offset + 1)
            if isinstance(node, ast.Attribute) and node.attr == "get_logger":
                yield Hit(span, f"`{cls.name}` derives from no class, yet {what}: a helper "
                          "class has no node's logger", "Give the class a logger of its own "
                          f"(`rclpy.logging.get_logger('{cls.name.lower()}')`) or pass it the "
                          "node's")
            else:
                yield Hit(span, f"`{cls.name}` derives from no class, yet {what}: its "
                          "instances are plain objects, not nodes (was `(Node)` left out of "
                          f"`class {cls.name}`?)", f"Write `class {cls.name}(Node):`")


def _instantiated_plain_classes(package: Package) -> dict[int, str]:
    """By ``id`` of the class node, the dotted name of each closed package class without
    bases from outside ``object`` that the package instantiates and no package class derives
    from."""
    classes = package_classes(package)
    made: set[str] = set()
    derived: set[str] = set()
    for _, _, index in installed_trees(package):
        for call in index.calls:
            if isinstance(call.func, ast.Name):
                found = package_class(call.func.id, index, package)
                made.update([found] if found else [])
        for cls in index.classes:
            for base in cls.bases:
                found = package_class(base.id, index, package) \
                    if isinstance(base, ast.Name) else None
                derived.update([found] if found else [])
    return {id(classes[dotted][0]): dotted for dotted in made - derived
            if closed_class(dotted, package)}


def _super_init_arguments(cls: ast.ClassDef) -> tuple[ast.AST, str] | None:
    """``super().__init__(...)`` with arguments in the ``__init__`` of a class without bases,
    which ``object.__init__`` rejects, with what it does."""
    if any(not (isinstance(base, ast.Name) and base.id == "object") for base in cls.bases):
        return None  # a package base in between may take the arguments
    for statement in cls.body:
        if isinstance(statement, ast.FunctionDef) and statement.name == "__init__":
            for node in ast.walk(statement):
                if is_super_init(node) and (node.args or node.keywords):  # type: ignore
                    return node, f"`{ast.unparse(node)}` passes arguments to " \
                        "`object.__init__`, which takes none (TypeError)"
    return None


def _node_method_read(cls: ast.ClassDef, dotted: str, index: Index, package: Package,
                      stores: dict | None, probed: frozenset[str]
                      ) -> tuple[ast.AST, str] | None:
    """The first read of ``self.<a Node method>`` in a plain method of ``cls`` that nothing
    defines or stores, with what it does."""
    if stores is None:
        return None  # attributes may be stored unseen
    own = attributes_of_class(dotted, package)
    for node in index.attributes:
        if node.attr in NODE_ATTRIBUTES and not node.attr.startswith("_") and \
                node.attr not in own and node.attr not in stores and \
                isinstance(node.value, ast.Name) and receiver_class(node.value, index) is cls \
                and not guarded(node, index, probed):
            return node, f"it reads `{ast.unparse(node)}`, an attribute of rclpy's `Node` " \
                "(AttributeError)"
    return None
