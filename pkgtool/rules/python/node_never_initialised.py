"""PYC041: a Node subclass whose ``__init__`` never runs the Node's own."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import subtree
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.knowledge.rclpy_node import NODE_ATTRIBUTES
from pkgtool.rules.node_api import node_subclasses
from pkgtool.rules.python._message_instances import attributes_taken, method_receiver
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import FUNCTIONS, Index, installed_trees


def _initialising(index: Index) -> set[int]:
    """The ids of the classes some method of which calls ``super().__init__``, ``super(C,
    self).__init__``, ``Base.__init__`` of one of the class's bases, ``self.__class__
    .__init__`` or ``getattr``: anything that may run the Node's constructor."""
    found: set[int] = set()
    for call in index.calls:
        func = call.func
        if isinstance(func, ast.Name) and func.id == "getattr" or \
                isinstance(func, ast.Attribute) and func.attr == "__init__":
            cls = index.enclosing_class(call)
            if cls is not None and _runs_a_base_init(cls, func, index):
                found.add(id(cls))
    return found


def _runs_a_base_init(cls: ast.ClassDef, func: ast.expr, index: Index) -> bool:
    if not isinstance(func, ast.Attribute):
        return True  # getattr
    owner = func.value
    if isinstance(owner, ast.Call) and isinstance(owner.func, ast.Name) and \
            owner.func.id in ("super", "type"):
        return True
    if isinstance(owner, ast.Attribute) and owner.attr == "__class__" or \
            ast.dump(owner) in {ast.dump(b) for b in cls.bases}:
        return True
    named = index.qualified(owner) if isinstance(owner, (ast.Name, ast.Attribute)) else None
    return named is not None and named in {index.qualified(b) for b in cls.bases}


def _abstract(init: ast.FunctionDef | ast.AsyncFunctionDef) -> bool:
    """True for an ``__init__`` that only raises (with a docstring, maybe)."""
    body = [s for s in init.body if not (isinstance(s, ast.Expr) and
                                         isinstance(s.value, ast.Constant))]
    return bool(body) and all(isinstance(s, ast.Raise) for s in body)


def _uninitialised(index: Index) -> Iterator[tuple[ast.ClassDef, ast.AST]]:
    """Node subclasses with an ``__init__`` of their own that runs no base's."""
    initialising: set[int] | None = None
    for cls in node_subclasses(index):
        if cls.decorator_list or cls.keywords:
            continue  # a metaclass or a decorator may build the instance another way
        init = next((s for s in cls.body if isinstance(s, FUNCTIONS) and
                     s.name == "__init__"), None)
        if init is None or _abstract(init):
            continue
        if initialising is None:
            initialising = _initialising(index)
        if id(cls) not in initialising and _used_as_node(cls, index):
            yield cls, init


_SPINS = frozenset({"spin", "spin_once", "spin_until_future_complete", "add_node"})
"""What takes a node to run it (rclpy's functions, an executor's methods)."""


def _used_as_node(cls: ast.ClassDef, index: Index) -> bool:
    """True when the class's methods use their receiver as a node (``self.get_logger()``,
    ``self.create_publisher``: a public attribute of rclpy's Node), or the module gives a new
    instance of it to a spin or ``add_node``; a class that only inherits from Node and works
    through a node it holds (``self.node``) is none."""
    for method in cls.body:
        receiver = method_receiver(method)
        if receiver and any(n.attr in NODE_ATTRIBUTES and not n.attr.startswith("_")
                            for n in attributes_taken(method, receiver)):
            return True
    for call in index.calls:
        func = call.func
        name = func.attr if isinstance(func, ast.Attribute) else \
            func.id if isinstance(func, ast.Name) else ""
        if name in _SPINS and any(isinstance(a, ast.Call) and isinstance(a.func, ast.Name) and
                                  a.func.id == cls.name for a in call.args):
            return True
    return False


@rule("PYC041", "node-never-initialised", Severity.ERROR,
      fix="Call the Node's constructor first in `__init__`: `super().__init__('my_node')`")
def node_never_initialised(package: Package) -> Iterator[Hit]:
    """A `Node` subclass defines `__init__` and never calls the Node's `__init__`.

    ## What it does
    Reports the `__init__` of a class deriving from rclpy's `Node` (or `LifecycleNode`, also
    through other classes of the module) when no method of the class calls
    `super().__init__(...)` or `Node.__init__(self, ...)`, and the class is used as a node:
    its methods use their receiver's Node API (`self.create_publisher`, `self.get_logger()`)
    or the module spins a new instance of it. A class that only inherits from Node and works
    through a node it holds (`self.node.get_logger()`) is left alone.

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
            bare = next((n for n in subtree(init) if isinstance(n, ast.Call) and
                         isinstance(n.func, ast.Attribute) and n.func.attr == "__init__" and
                         isinstance(n.func.value, ast.Name) and n.func.value.id == "super"),
                        None)
            if bare is not None:  # `super.__init__(...)`: the class `super`, not a call of it
                yield Hit(Span(module.path, bare.lineno, bare.col_offset + 1),
                          f"`{cls.name}.__init__` calls `super.__init__(...)`, not "
                          "`super().__init__(...)`: the line raises TypeError (descriptor "
                          "'__init__' requires a 'super' object)", "Write `super().__init__(`")
                continue
            yield Hit(Span(module.path, init.lineno, init.col_offset + 1),  # type: ignore
                      f"`{cls.name}.__init__` never calls `super().__init__(...)`: the Node is "
                      "not set up, and its first rclpy call raises AttributeError")
