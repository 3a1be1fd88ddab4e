"""PYC046: a method of an rclpy object (``future.result``) or ``rclpy.ok`` used without ``()``."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import nodes_of_class, subtree
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import ACTION_CLIENTS, NODE_CLASSES
from pkgtool.rules.python._message_instances import (binding_counts, callback_function, kept,
                                                     method_receiver)
from pkgtool.rules.python._value_types import attribute_stores, receiver_class
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, installed_trees

METHODS = {"future": frozenset({"result", "done", "exception", "cancelled"}),
           "client": frozenset({"service_is_ready", "wait_for_service"}),
           "action client": frozenset({"server_is_ready", "wait_for_server"}),
           "clock": frozenset({"now"})}
"""What rclpy objects of each kind have as methods that code calls for their result."""
_FUTURE_MAKERS = frozenset({"call_async", "send_goal_async", "get_result_async",
                            "cancel_goal_async"})
_OK = frozenset({"rclpy.ok", "rclpy.utilities.ok"})
_TESTS = (ast.If, ast.While, ast.IfExp, ast.Assert)


def _made(value: ast.expr | None, index: Index) -> str | None:
    """The kind of rclpy object ``value`` makes (a key of :data:`METHODS`), if it is a call
    that makes one; ``none`` for the constant None."""
    if isinstance(value, ast.Constant) and value.value is None:
        return "none"
    if not isinstance(value, ast.Call):
        return None
    func = value.func
    if isinstance(func, ast.Attribute) and func.attr in _FUTURE_MAKERS:
        return "future"
    if isinstance(func, ast.Attribute) and func.attr == "create_client":
        return "client"
    if isinstance(func, ast.Attribute) and func.attr == "get_clock" and not value.args:
        return "clock"
    if isinstance(func, (ast.Name, ast.Attribute)) and index.qualified(func) in ACTION_CLIENTS:
        return "action client"
    return None


def _agreed(kinds: list[str | None]) -> str | None:
    """The one kind all bindings give (None constants aside), if there is one."""
    found = set(kinds) - {"none"}
    return next(iter(found)) if len(found) == 1 and None not in found else None


def _local_values(tree: ast.Module, index: Index) -> dict[tuple[int, str], list[ast.expr]]:
    """``name = value`` assignments by (id of the function they are in, name)."""
    found: dict[tuple[int, str], list[ast.expr]] = {}
    for node in nodes_of_class(tree, ast.Assign):
        assert isinstance(node, ast.Assign)
        target = node.targets[0]
        function = index.enclosing_function(node, through_lambdas=False)
        if len(node.targets) == 1 and isinstance(target, ast.Name) and function is not None:
            found.setdefault((id(function), target.id), []).append(node.value)
    return found


def _local_kind(name: ast.Name, tree: ast.Module, index: Index) -> str | None:
    """The kind of rclpy object a function's local ``name`` holds: every binding of it in the
    function (nested ones included) an assignment making one, or None."""
    function = index.enclosing_function(name, through_lambdas=False)
    if function is None:
        return None
    assignments = kept(tree, "local assignments", lambda: _local_values(tree, index))
    values = assignments.get((id(function), name.id), [])
    if len(values) != binding_counts(function)[name.id]:
        return None
    return _agreed([_made(value, index) for value in values])


def _class_stores(cls: ast.ClassDef, name: str, index: Index) -> list[ast.Attribute]:
    """The stores of ``<receiver>.name`` in the plain methods of ``cls``."""
    found = []
    for node in subtree(cls):
        if isinstance(node, ast.Attribute) and node.attr == name and \
                not isinstance(node.ctx, ast.Load) and isinstance(node.value, ast.Name):
            method = index.enclosing_function(node, through_lambdas=False)
            if index.parents.get(id(method)) is cls and method_receiver(method) == node.value.id:
                found.append(node)
    return found


def _attribute_kind(value: ast.Attribute, package: Package, index: Index) -> str | None:
    """The kind of rclpy object ``self.x`` holds: every store of ``x`` an assignment making
    one (or None); the stores of the class when it derives from rclpy's node classes alone,
    else those of an attribute ``x`` anywhere in the package."""
    cls = receiver_class(value.value, index)
    everywhere = attribute_stores(package) if cls is not None else None
    if not everywhere or value.attr not in everywhere:
        return None  # not a method's receiver, attributes stored unseen, or never stored
    assert cls is not None
    own = bool(cls.bases) and all(index.qualified(b) in NODE_CLASSES for b in cls.bases)
    stores = [(n, index) for n in _class_stores(cls, value.attr, index)] if own else \
        everywhere[value.attr]
    kinds: list[str | None] = []
    for store, store_index in stores:
        parent = store_index.parents.get(id(store))
        single = isinstance(parent, ast.Assign) and parent.targets == [store]
        kinds.append(_made(parent.value, store_index) if single else None)  # type: ignore
    return _agreed(kinds)


def _done_callback_futures(tree: ast.Module, index: Index) -> set[int]:
    """Ids of the names that are the future a done callback is given: the first parameter
    (after the receiver) of a function passed to ``add_done_callback``, never rebound."""
    found: set[int] = set()
    for call in index.calls:
        func = call.func
        if not (isinstance(func, ast.Attribute) and func.attr == "add_done_callback" and
                len(call.args) == 1):
            continue
        named = callback_function(call.args[0], tree, index)
        if named is None:
            continue
        function, skip = named
        parameters = [*function.args.posonlyargs, *function.args.args]
        if len(parameters) <= skip or binding_counts(function)[parameters[skip].arg] != 1:
            continue
        parameter = parameters[skip].arg
        found.update(id(n) for n in subtree(function)
                     if isinstance(n, ast.Name) and n.id == parameter)
    return found


def _kind(value: ast.expr, package: Package, tree: ast.Module, index: Index,
          futures: set[int]) -> str | None:
    if isinstance(value, ast.Name):
        return "future" if id(value) in futures else _local_kind(value, tree, index)
    if isinstance(value, ast.Attribute):
        return _attribute_kind(value, package, index)
    return _made(value, index) if isinstance(value, ast.Call) else None


def _tested(node: ast.expr, index: Index) -> bool:
    """True when ``node``'s truth is what its place uses: an ``if``/``while`` test, an operand
    of ``not``, ``and``, ``or``."""
    parent = index.parents.get(id(node))
    return isinstance(parent, _TESTS) and parent.test is node or \
        isinstance(parent, ast.UnaryOp) and isinstance(parent.op, ast.Not) or \
        isinstance(parent, ast.BoolOp)


def _uncalled(node: ast.expr, index: Index) -> bool:
    """True unless ``node`` is called, or passed to a call (a callable given on purpose)."""
    parent = index.parents.get(id(node))
    return not (isinstance(parent, ast.Call) and (
        parent.func is node or any(a is node for a in parent.args) or
        any(k.value is node for k in parent.keywords)))


def _uncalled_methods(package: Package, tree: ast.Module, index: Index
                      ) -> Iterator[tuple[ast.expr, str]]:
    """(node, kind of object) of the methods of :data:`METHODS` taken without a call, and
    ``rclpy.ok`` tested without one (kind ``rclpy``)."""
    wanted = frozenset().union(*METHODS.values())
    futures: set[int] | None = None
    for node in index.attributes:
        if node.attr == "ok" and index.qualified(node) in _OK and _tested(node, index):
            yield node, "rclpy"
        if node.attr not in wanted or not _uncalled(node, index):
            continue
        if futures is None:
            futures = _done_callback_futures(tree, index)
        kind = _kind(node.value, package, tree, index, futures)
        if kind is not None and node.attr in METHODS.get(kind, ()):
            yield node, kind
    for name in nodes_of_class(tree, ast.Name):
        assert isinstance(name, ast.Name)
        if name.id == "ok" and index.qualified(name) in _OK and _tested(name, index):
            yield name, "rclpy"


def _message(node: ast.expr, kind: str, index: Index) -> str:
    text = ast.unparse(node)
    what = "a function" if kind == "rclpy" else f"a method of rclpy's {kind}"
    if _tested(node, index):
        return (f"`{text}` is {what}, tested without calling it: a function is always true, "
                f"so the test never changes")
    parent = index.parents.get(id(node))
    effect = f" (`{ast.unparse(parent)}` raises AttributeError)" \
        if isinstance(parent, ast.Attribute) else \
        " (the statement does nothing)" if isinstance(parent, ast.Expr) else ""
    return (f"`{text}` is {what}, used without calling it: this is the method itself, not "
            f"what it returns{effect}")


@rule("PYC046", "method-not-called", Severity.ERROR,
      fix="Call it: `future.result()`, `rclpy.ok()`")
def method_not_called(package: Package) -> Iterator[Hit]:
    """A method of an rclpy object, or `rclpy.ok`, is used without calling it.

    ## What it does
    Reports `result`, `done`, `exception` and `cancelled` of a future (what `call_async()`,
    `send_goal_async()`, `get_result_async()` and `cancel_goal_async()` return, and the
    parameter of a done callback), `service_is_ready` and `wait_for_service` of a client,
    `server_is_ready` and `wait_for_server` of an action client, and `now` of
    `get_clock()`, taken without `()` (not when passed to a call: a callable given on
    purpose), and `rclpy.ok` tested without `()`. A local name or a node's `self.x` counts
    when every assignment of it makes such an object (or None).

    ## Why is this bad?
    Without `()` the code has the bound method, not its result: `future.result.sum` raises
    `AttributeError: 'builtin_function_or_method' object has no attribute 'sum'`, and a method
    is always true, so `while rclpy.ok:` never ends and `if future.done:` always passes.

    ## Example
    ```python
    def on_response(self, future):
        self.get_logger().info(f'Sum: {future.result.sum}')
    ```

    ## Use instead
    ```python
    def on_response(self, future):
        self.get_logger().info(f'Sum: {future.result().sum}')
    ```
    """
    for module, tree, index in installed_trees(package):
        if not index.imports_from("rclpy"):
            continue
        for node, kind in _uncalled_methods(package, tree, index):
            yield Hit(Span(module.path, node.lineno, node.col_offset + 1),
                      _message(node, kind, index), f"Call it: `{ast.unparse(node)}()`")
