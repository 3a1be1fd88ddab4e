"""PYC096: a node assigns one of rclpy's read-only ``Node`` properties (``self.timers = []``)."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import subtree
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import node_subclasses
from pkgtool.rules.python._assignments import receiver_store
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, installed_trees

READ_ONLY = frozenset({"clients", "context", "default_callback_group", "guards", "handle",
                       "publishers", "services", "subscriptions", "timers", "waitables"})
"""Properties of rclpy's ``Node`` without a setter (``handle``'s setter raises), Humble to
Rolling: assigning one raises AttributeError."""


def _defines(cls: ast.ClassDef, name: str, index: Index) -> bool:
    """True when ``cls`` or a base class of the module defines ``name`` in its body."""
    bases = {b.id for b in cls.bases if isinstance(b, ast.Name)}
    return any(isinstance(s, (ast.FunctionDef, ast.AsyncFunctionDef)) and s.name == name or
               isinstance(s, (ast.Assign, ast.AnnAssign)) and any(
                   isinstance(t, ast.Name) and t.id == name
                   for t in (s.targets if isinstance(s, ast.Assign) else [s.target]))
               for s in cls.body) or \
        any(_defines(other, name, index) for other in index.classes if other.name in bases
            and other is not cls)


@rule("PYC096", "node-property-assigned", Severity.ERROR,
      fix="Keep your own list under another name: `self.my_timers = []`")
def node_property_assigned(package: Package) -> Iterator[Hit]:
    """A node class assigns one of rclpy's read-only `Node` properties.

    ## What it does
    Reports `self.x = ...` (also augmented or annotated) in a method of a class deriving from
    rclpy's `Node` or `LifecycleNode` when `x` is one of the properties rclpy's `Node` defines
    without a setter: `publishers`, `subscriptions`, `timers`, `clients`, `services`,
    `guards`, `waitables`, `context`, `default_callback_group`, and `handle` (whose setter
    raises). A class (or a base class of the module) defining `x` itself is left alone.

    ## Why is this bad?
    The assignment raises `AttributeError: property 'timers' of 'Talker' object has no
    setter` (checked on Jazzy): the node dies in `__init__`. Keeping one's own list of timers
    or subscriptions is fine under another name; rclpy already keeps them (`self.timers`
    lists them).

    ## Example
    ```python
    class Talker(Node):
        def __init__(self):
            super().__init__('talker')
            self.timers = []
    ```

    ## Use instead
    ```python
    class Talker(Node):
        def __init__(self):
            super().__init__('talker')
            self.my_timers = []
    ```
    """
    for module, _, index in installed_trees(package):
        for cls in node_subclasses(index):
            for node in subtree(cls):
                if isinstance(node, ast.Attribute) and node.attr in READ_ONLY and \
                        isinstance(node.ctx, ast.Store) and receiver_store(node, index) is cls \
                        and not _defines(cls, node.attr, index):
                    yield Hit(Span(module.path, node.lineno, node.col_offset + 1),
                              f"`{ast.unparse(node)}` is a read-only property of rclpy's "
                              f"`Node`: assigning it raises AttributeError (property "
                              f"'{node.attr}' has no setter)")
