"""PYC009: a Node constructed without a node name."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import is_super_init, nodes_of_class
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import NODE_CLASSES, name_argument, node_constructions, unpacks
from pkgtool.rules.scopes import scope_bindings
from pkgtool.rules.syntax_trees import Index, installed_trees
from pkgtool.rules.registry import rule


def _forwarded(call: ast.Call, index: Index) -> str | None:
    """The name of the class whose ``__init__`` makes ``call``, a ``super().__init__()``
    giving no node name, when all it gives is that ``__init__``'s own ``*args`` and
    ``**kwargs``, used nowhere else (so the name can only come from the class's caller)."""
    init = index.enclosing_function(call)
    cls = index.parents.get(id(init)) if init is not None else None
    if init is None or init.name != "__init__" or not isinstance(cls, ast.ClassDef):
        return None
    packed = {a.arg for a in (init.args.vararg, init.args.kwarg) if a is not None}
    given = [a.value for a in call.args if isinstance(a, ast.Starred)] + \
        [k.value for k in call.keywords if k.arg is None]
    if len(given) != len(call.args) + sum(k.arg is None for k in call.keywords) or \
            not given or any(not isinstance(g, ast.Name) or g.id not in packed for g in given):
        return None
    reads = [n for n in nodes_of_class(init, ast.Name) if isinstance(n, ast.Name) and
             n.id in packed]
    return cls.name if len(reads) == len(given) else None


def _reaches_another_base(call: ast.Call, index: Index) -> bool:
    """True for ``super().__init__()`` in a class whose first base is not the node class it
    initialises by name in the same method (``class W(Thread, Node)``: ``super().__init__()``
    is ``Thread.__init__``, then ``Node.__init__(self, 'worker')``), or that starts the lookup
    after a base listed after the node class (``super(QWidget, self).__init__()`` in ``class
    A(Node, QWidget)`` is ``QObject.__init__``)."""
    if not is_super_init(call):
        return False
    init = index.enclosing_function(call)
    cls = index.parents.get(id(init)) if init is not None else None
    if init is None or not isinstance(cls, ast.ClassDef) or len(cls.bases) < 2:
        return False
    start = call.func.value.args[0] if call.func.value.args else None  # type: ignore
    names = [ast.unparse(base) for base in cls.bases]
    node_at = next((i for i, base in enumerate(cls.bases)
                    if (index.qualified(base) or "") in NODE_CLASSES), None)
    if isinstance(start, ast.Name) and start.id in names and node_at is not None and \
            names.index(start.id) > node_at:
        return True  # super(QWidget, self) in class A(Node, QWidget): the lookup skips Node
    later = {ast.unparse(base) for base in cls.bases[1:]
             if (index.qualified(base) or "") in NODE_CLASSES}
    return any(isinstance(c.func, ast.Attribute) and c.func.attr == "__init__" and
               ast.unparse(c.func.value) in later and c.args and
               isinstance(c.args[0], ast.Name) and c.args[0].id == "self"
               for c in nodes_of_class(init, ast.Call) if isinstance(c, ast.Call))


def _unnamed_constructions(tree: ast.Module, index: Index, name: str) -> Iterator[ast.Call]:
    """Calls of the module's class ``name`` (bound once, by its ``class`` statement) that
    give no argument but keywords other than ``node_name``."""
    if scope_bindings(tree)[name] != 1 or name not in {c.name for c in tree.body
                                                       if isinstance(c, ast.ClassDef)}:
        return
    for call in index.calls:
        if isinstance(call.func, ast.Name) and call.func.id == name and not call.args and \
                all(k.arg not in (None, "node_name") for k in call.keywords) and \
                not any(scope_bindings(f)[name] for f in index.functions_around(call)):
            yield call


@rule("PYC009", "missing-node-name", Severity.ERROR,
      fix="Pass the node name: `super().__init__('my_node')`")
def missing_node_name(package: Package) -> Iterator[Hit]:
    """A `Node` is constructed without a node name.

    ## What it does
    Reports `super().__init__()` in classes derived from rclpy's `Node` (or `LifecycleNode`),
    and `Node()` or `rclpy.create_node()` calls, that pass no node name. Calls with `*args`
    or `**kwargs` are not checked, but for one case: a node class whose `__init__` gives
    `super().__init__()` nothing but its own `*args` and `**kwargs` (used nowhere else in
    it, `super().__init__(**kwargs)`), constructed in the same module with no positional
    argument and no `node_name=` (`Talker()`). Forwarding the arguments is correct code when
    the caller names the node (`Talker(node_name='talker')`). Nor is `super().__init__()` in
    a class whose first base is another class and whose `__init__` initialises its node base
    by name (`class Worker(Thread, Node)`: `super().__init__()` is `Thread.__init__()`, then
    `Node.__init__(self, 'worker')`).

    ## Why is this bad?
    `node_name` is a required argument of `Node.__init__`: the node dies at start-up with
    `TypeError: __init__() missing 1 required positional argument: 'node_name'`. ROS 1's
    `rospy.init_node()` took the name elsewhere, so ported code often leaves it out.

    ## Example
    ```python
    class Talker(Node):
        def __init__(self):
            super().__init__()
    ```

    ## Use instead
    ```python
    class Talker(Node):
        def __init__(self):
            super().__init__('talker')
    ```
    """
    for module, tree, index in installed_trees(package):
        for call in node_constructions(index):
            if name_argument(call) is not None or _reaches_another_base(call, index):
                continue
            if not unpacks(call):
                yield Hit(Span(module.path, call.lineno, call.col_offset + 1),
                          "The node is created without a name")
            elif (name := _forwarded(call, index)) is not None:
                for made in _unnamed_constructions(tree, index, name):
                    yield Hit(Span(module.path, made.lineno, made.col_offset + 1),
                              f"`{ast.unparse(made)}` gives no node name, and "
                              f"`{name}.__init__` passes `Node.__init__` only what it is "
                              "given: it raises `TypeError: missing 1 required positional "
                              "argument: 'node_name'`",
                              f"Pass the name, `{name}(node_name='my_node')`, or give "
                              f"it in `{name}.__init__`: `super().__init__('my_node', "
                              "**kwargs)`")
