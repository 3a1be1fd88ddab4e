"""PYC017: ``rclpy.spin()`` or ``executor.add_node()`` given no node, or the node class."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.memo import per_tree
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import (ACTION_PARAMETERS, ACTIONS, ADD_NODE, NODE_CLASSES, SPINS,
                                    node_subclasses, unpacks)
from pkgtool.rules.registry import rule
from pkgtool.rules.scopes import scope_bindings, scope_walk
from pkgtool.rules.syntax_trees import Index, installed_trees

_RCLPY_NODES = NODE_CLASSES - {"rclpy.create_node"}
"""rclpy's node classes themselves."""

Scope = ast.Module | ast.FunctionDef | ast.AsyncFunctionDef


def _scopes(node: ast.AST, tree: ast.Module, index: Index) -> list[Scope]:
    """The functions around ``node``, innermost first, then the module."""
    return [*index.functions_around(node), tree]


def _values(name: str, scopes: list[Scope]) -> list[ast.expr]:
    """What ``name`` may hold where it is read: the values of the plain assignments (``name =
    value``) of the innermost scope binding it; nothing when it is bound any other way too
    there (a parameter, a loop, a tuple target, ``global``)."""
    scope = next((s for s in scopes if scope_bindings(s)[name]), None)
    if scope is None:
        return []
    values = _assigned(scope).get(name, [])
    return values if len(values) == scope_bindings(scope)[name] else []


@per_tree
def _assigned(scope: Scope) -> dict[str, list[ast.expr]]:
    """The values of the plain assignments (``name = value``) of ``scope``, by name."""
    found: dict[str, list[ast.expr]] = {}
    for node in scope_walk(scope.body):
        if isinstance(node, (ast.Assign, ast.AnnAssign)) and node.value is not None:
            for target in node.targets if isinstance(node, ast.Assign) else [node.target]:
                if isinstance(target, ast.Name):
                    found.setdefault(target.id, []).append(node.value)
    return found


def _class_named(value: ast.expr, classes: set[str], scopes: list[Scope], index: Index
                 ) -> str | None:
    """The name of the module's Node subclass that ``value`` names, if it is one: bound
    once, by its ``class`` statement, and in no function around the read; or of rclpy's
    node class itself (``Node``, imported and bound no other way)."""
    if isinstance(value, ast.Name) and value.id in classes \
            and scope_bindings(scopes[-1])[value.id] == 1 \
            and not any(scope_bindings(s)[value.id] for s in scopes[:-1]):
        return value.id
    if isinstance(value, (ast.Name, ast.Attribute)) and index.qualified(value) in _RCLPY_NODES:
        return ast.unparse(value)
    return None


def _node_class(value: ast.expr, classes: set[str], scopes: list[Scope], index: Index
                ) -> str | None:
    """The node class that ``value`` certainly is (the class, not an instance): its name,
    or a variable only ever assigned it (or None)."""
    direct = _class_named(value, classes, scopes, index)
    if direct or not isinstance(value, ast.Name) or value.id in classes:
        return direct
    found = {_class_named(v, classes, scopes, index) for v in _values(value.id, scopes)
             if not (isinstance(v, ast.Constant) and v.value is None)}
    return found.pop() if len(found) == 1 and None not in found else None


def _is_executor(value: ast.expr, index: Index, scopes: list[Scope]) -> bool:
    """True for a variable only ever assigned an rclpy executor (``SingleThreadedExecutor()``)."""
    values = _values(value.id, scopes) if isinstance(value, ast.Name) else []
    names = [index.qualified(v.func) if isinstance(v, ast.Call) else None
             for v in values]
    return bool(names) and all(n and n.startswith("rclpy.") and n.endswith("Executor")
                               for n in names)


def _problem(call: ast.Call, required: tuple[str, ...], classes: set[str],
             scopes: list[Scope], index: Index) -> str | None:
    """What is wrong with the node passed to a spin, ``add_node`` or action call, if
    anything."""
    if unpacks(call):
        return None
    node = call.args[0] if call.args else next(
        (k.value for k in call.keywords if k.arg == "node"), None)
    given = len(call.args) + sum(k.arg in required for k in call.keywords)
    if node is None:
        return "is given no node: it raises `TypeError`; pass the node object"
    if given < len(required):
        return f"takes the node and the {required[-1]}: it raises `TypeError`"
    cls = _node_class(node, classes, scopes, index)
    if cls and required == ACTION_PARAMETERS:
        return f"is given the class `{cls}`, not a node: it raises `AttributeError: " \
               "'property' object has no attribute`; pass the node object (`self` in a " \
               "method of the node)"
    if cls:
        return f"is given the class `{cls}`, not a node: spinning it raises `TypeError`; " \
               f"create the node with `{cls}()` and pass that"
    return None


@rule("PYC017", "spin-without-node", Severity.ERROR,
      fix="Create the node and pass it: `node = Talker()`, then `rclpy.spin(node)`")
def spin_without_node(package: Package) -> Iterator[Hit]:
    """`rclpy.spin()` or an executor's `add_node()` is given no node, or the node class.

    ## What it does
    Checks the node argument of `rclpy.spin`, `rclpy.spin_once`,
    `rclpy.spin_until_future_complete`, of `add_node` on a variable only ever assigned an
    rclpy executor (`executor = SingleThreadedExecutor()`), and of rclpy's `ActionClient`
    and `ActionServer`, in installed modules. Reports a call that passes no node (or, for
    `spin_until_future_complete`, no future), and one that passes a node class instead of
    an instance of it: a `Node` subclass defined in the module or rclpy's `Node` itself,
    by its name or through a variable whose every assignment is the class (or `None`).
    Calls with `*args` or `**kwargs`, names bound any other way (parameters, loops) and any
    other expression are not checked.

    ## Why is this bad?
    `rclpy.spin()` raises `TypeError: spin() missing 1 required positional argument: 'node'`
    at start-up; passing the class (`rclpy.spin(Talker)`, `node = Talker`) fails inside the
    executor as soon as it spins, with `TypeError: 'property' object is not iterable`, a
    message that does not point at the missing parentheses. `ActionClient(FibClient, ...)`
    or `ActionServer(Node, ...)` raises `AttributeError: 'property' object has no attribute
    'add_entity'` in the node's constructor.

    ## Example
    ```python
    rclpy.init(args=args)
    rclpy.spin(Talker)
    ```

    ## Use instead
    ```python
    rclpy.init(args=args)
    rclpy.spin(Talker())
    ```
    """
    for module, tree, index in installed_trees(package):
        if not any(i.top_level == "rclpy" for i in module.imports):
            continue
        classes = {c.name for c in node_subclasses(index) if c in tree.body}
        for call in index.calls:
            target = index.qualified(call.func)
            required = ACTION_PARAMETERS if target in ACTIONS else SPINS.get(target or "")
            if required is None and isinstance(call.func, ast.Attribute) and \
                    call.func.attr == ADD_NODE and target is None:
                scopes = _scopes(call, tree, index)
                required = ("node",) if _is_executor(call.func.value, index, scopes) else None
            if required is None:
                continue
            problem = _problem(call, required, classes, _scopes(call, tree, index), index)
            if problem:
                shown = target or ast.unparse(call.func)
                yield Hit(Span(module.path, call.lineno, call.col_offset + 1),
                          f"`{shown}()` {problem}")
