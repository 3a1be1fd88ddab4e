"""PYC059: a function starts rclpy and makes a node with callbacks, and nothing spins it."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import nodes_of_class, subtree
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import ACTION_SERVERS, ADD_NODE, INITS, node_subclasses
from pkgtool.rules.python._assignments import is_none
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, installed_trees

REGISTERS = {"create_timer": "a timer", "create_subscription": "a subscription",
             "create_service": "a service"}
"""The node methods that register a callback only an executor runs, and what they make."""
QUIET_METHODS = frozenset({"destroy_node", "get_logger", "get_name", "get_namespace",
                           "get_clock"})
"""Node methods a function may call on its node without running any of its callbacks."""
EXECUTOR_METHODS = frozenset({ADD_NODE, "remove_node", "shutdown", "get_nodes"})
"""Executor methods that run no callback."""


def _callbacks(cls: ast.ClassDef, index: Index) -> str | None:
    """What ``cls`` registers for an executor to run (``a timer``), if anything."""
    for node in subtree(cls):
        if isinstance(node, ast.Call):
            func = node.func
            if isinstance(func, ast.Attribute) and func.attr in REGISTERS:
                return REGISTERS[func.attr]
            if index.qualified(func) in ACTION_SERVERS:
                return "an action server"
    return None


def _spins_anything(tree: ast.Module) -> bool:
    """True when the module mentions any spin function or method (``rclpy.spin``,
    ``executor.spin_once``, ``spin`` imported by name): it may run callbacks in ways this rule
    does not follow."""
    return any(isinstance(n, ast.Attribute) and n.attr.startswith("spin") or
               isinstance(n, ast.Name) and n.id.startswith("spin") or
               isinstance(n, ast.alias) and n.name.startswith("spin")
               for n in nodes_of_class(tree, ast.Attribute, ast.Name, ast.alias))


def _method_called(name: ast.Name, methods: frozenset[str], index: Index) -> str | None:
    """The method of ``methods`` called on ``name`` (``name.method(...)``), if that is the
    read; ``add_node`` for ``executor.add_node(name)``, ``is None`` for a test against None."""
    parent = index.parents.get(id(name))
    call = index.parents.get(id(parent))
    if isinstance(parent, ast.Attribute) and parent.attr in methods and \
            isinstance(call, ast.Call) and call.func is parent:
        return parent.attr
    if isinstance(parent, ast.Compare) and len(parent.ops) == 1 and \
            isinstance(parent.ops[0], (ast.Is, ast.IsNot)) and is_none(parent.comparators[0]):
        return "is None"
    if isinstance(parent, ast.Call) and parent.args == [name] and not parent.keywords and \
            isinstance(parent.func, ast.Attribute) and parent.func.attr == ADD_NODE:
        return ADD_NODE
    return None


def _only_quietly_used(name: str, function: ast.AST, index: Index,
                       methods: frozenset[str] = QUIET_METHODS) -> bool:
    """True when every read of ``name`` in ``function`` calls one of ``methods`` on it, or
    adds it to an executor (a local name) that is only ever given nodes and shut down: the
    node goes nowhere else (no thread, no helper, no loop of its own methods)."""
    for node in subtree(function):
        if not (isinstance(node, ast.Name) and node.id == name and
                isinstance(node.ctx, ast.Load)):
            continue
        used = _method_called(node, methods, index)
        if used is None:
            return False
        if used == ADD_NODE and methods is QUIET_METHODS:
            executor = index.parents.get(id(node)).func.value  # type: ignore[union-attr]
            if not (isinstance(executor, ast.Name) and
                    _only_quietly_used(executor.id, function, index, EXECUTOR_METHODS)):
                return False
    return True


def _unspun(function: ast.FunctionDef | ast.AsyncFunctionDef, classes: dict[str, str],
            index: Index) -> Iterator[tuple[ast.Call, str]]:
    """The constructions of a node class with callbacks in ``function`` (which starts rclpy)
    whose node only ever has quiet methods called, with what the class registers."""
    for node in subtree(function):
        if not (isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and
                node.func.id in classes):
            continue
        parent = index.parents.get(id(node))
        if isinstance(parent, ast.Expr) or isinstance(parent, ast.Assign) and \
                len(parent.targets) == 1 and isinstance(parent.targets[0], ast.Name) and \
                _only_quietly_used(parent.targets[0].id, function, index):
            yield node, classes[node.func.id]


@rule("PYC059", "node-never-spun", Severity.ERROR,
      fix="Spin the node: `rclpy.spin(node)` (or add it to an executor and spin that)")
def node_never_spun(package: Package) -> Iterator[Hit]:
    """A function starts rclpy and makes a node with callbacks, and nothing spins it.

    ## What it does
    Reports the construction of a node class of the module that registers callbacks (a
    timer, a subscription, a service or an action server) in a function that calls
    `rclpy.init()`, when the node is only kept in a local name whose only use is calling
    `destroy_node()`, `get_logger()` and the like on it or adding it to an executor that is
    never spun, and the module mentions no spin at all (`rclpy.spin*`, an executor's `spin*`,
    a `spin` imported by name): then nothing can run its callbacks. A node passed to a helper
    or a thread, or one whose own methods the function calls, is left alone.

    ## Why is this bad?
    rclpy runs a node's callbacks only while an executor spins it. Without a spin the
    function creates the node, reaches its clean-up and returns: the program exits at once,
    and the timer, subscription or service never runs, silently.

    ## Example
    ```python
    def main():
        rclpy.init()
        node = Talker()
        node.destroy_node()
        rclpy.shutdown()
    ```

    ## Use instead
    ```python
    def main():
        rclpy.init()
        node = Talker()
        rclpy.spin(node)
        node.destroy_node()
        rclpy.shutdown()
    ```
    """
    for module, tree, index in installed_trees(package):
        if not index.imports_from("rclpy") or _spins_anything(tree):
            continue
        classes = {cls.name: made for cls in node_subclasses(index)
                   if (made := _callbacks(cls, index)) is not None}
        if not classes:
            continue
        starts = {id(index.enclosing_function(c)) for c in index.calls
                  if index.qualified(c.func) in INITS}
        for function in index.functions:
            if id(function) not in starts:
                continue
            for call, made in _unspun(function, classes, index):
                yield Hit(Span(module.path, call.lineno, call.col_offset + 1),
                          f"`{ast.unparse(call)}` makes a node with {made}, but nothing spins "
                          f"it: `{function.name}()` returns and its callbacks never run")
