"""PYC041: a Node subclass whose ``__init__`` never runs the Node's own."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import node_subclasses
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import FUNCTIONS, Index, installed_trees


def _runs_a_base_init(cls: ast.ClassDef) -> bool:
    """True when some method of ``cls`` calls ``super().__init__``, ``super(C, self)
    .__init__`` or ``Base.__init__`` of one of its bases, or ``__init__`` through
    ``getattr``/``type``: anything that may run the Node's constructor."""
    bases = {ast.dump(b) for b in cls.bases}
    for call in nodes_of_class(cls, ast.Call):
        func = call.func  # type: ignore[attr-defined]
        if not isinstance(func, ast.Attribute) or func.attr != "__init__":
            if isinstance(func, ast.Name) and func.id == "getattr":
                return True
            continue
        owner = func.value
        if isinstance(owner, ast.Call) and isinstance(owner.func, ast.Name) and \
                owner.func.id in ("super", "type"):
            return True
        if ast.dump(owner) in bases or isinstance(owner, ast.Attribute) and \
                owner.attr == "__class__":
            return True
    return False


def _abstract(init: ast.FunctionDef | ast.AsyncFunctionDef) -> bool:
    """True for an ``__init__`` that only raises (with a docstring, maybe)."""
    body = [s for s in init.body if not (isinstance(s, ast.Expr) and
                                         isinstance(s.value, ast.Constant))]
    return bool(body) and all(isinstance(s, ast.Raise) for s in body)


def _uninitialised(index: Index) -> Iterator[tuple[ast.ClassDef, ast.AST]]:
    """Node subclasses with an ``__init__`` of their own that runs no base's."""
    for cls in node_subclasses(index):
        if cls.decorator_list or cls.keywords:
            continue  # a metaclass or a decorator may build the instance another way
        init = next((s for s in cls.body if isinstance(s, FUNCTIONS) and
                     s.name == "__init__"), None)
        if init is not None and not _abstract(init) and not _runs_a_base_init(cls):
            yield cls, init


@rule("PYC041", "node-never-initialised", Severity.ERROR,
      fix="Call the Node's constructor first in `__init__`: `super().__init__('my_node')`")
def node_never_initialised(package: Package) -> Iterator[Hit]:
    """A `Node` subclass defines `__init__` and never calls the Node's `__init__`.

    ## What it does
    Reports the `__init__` of a class deriving from rclpy's `Node` (or `LifecycleNode`, also
    through other classes of the module) when no method of the class calls
    `super().__init__(...)` or `Node.__init__(self, ...)`.

    ## Why is this bad?
    The Node's constructor creates the node in the ROS graph and the attributes every
    method uses. Without it the first rclpy call on `self` fails:
    `self.create_publisher(...)` raises `AttributeError: 'Talker' object has no attribute
    '_default_callback_group'`, `self.get_logger()` one about `_logger`, and spinning the
    object one about `_Node__executor_weakref`. The node never starts.

    ## Example
    ```python
    class Talker(Node):
        def __init__(self):
            self.publisher = self.create_publisher(String, 'chatter', 10)
    ```

    ## Use instead
    ```python
    class Talker(Node):
        def __init__(self):
            super().__init__('talker')
            self.publisher = self.create_publisher(String, 'chatter', 10)
    ```
    """
    for module, _, index in installed_trees(package):
        for cls, init in _uninitialised(index):
            yield Hit(Span(module.path, init.lineno, init.col_offset + 1),  # type: ignore
                      f"`{cls.name}.__init__` never calls `super().__init__(...)`: the Node is "
                      "not set up, and its first rclpy call raises AttributeError")
