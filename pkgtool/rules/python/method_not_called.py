"""PYC046: a method of an rclpy object (``future.result``) or ``rclpy.ok`` used without ``()``."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import TRIES, descendants, nodes_of_class, subtree
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import ACTION_CLIENTS, bases_are_nodes
from pkgtool.rules.python._assignments import (assigned_values, done_callback_futures,
                                               is_none)
from pkgtool.rules.python._loggers import LEVELS
from pkgtool.rules.python._value_types import receiver_class
from pkgtool.rules.registry import rule
from pkgtool.rules.scopes import bound_names
from pkgtool.rules.syntax_trees import FUNCTIONS, Index, installed_trees

METHODS = {"future": frozenset({"result", "done", "exception", "cancelled"}),
           "client": frozenset({"service_is_ready", "wait_for_service"}),
           "action client": frozenset({"server_is_ready", "wait_for_server"}),
           "clock": frozenset({"now"}),
           "node": frozenset({"get_logger", "get_clock", "get_name", "get_namespace",
                              "get_fully_qualified_name"})}
"""What rclpy objects of each kind have as methods that code calls for their result."""
_ALIASED = frozenset({"node"})
"""Kinds whose methods code may keep uncalled on purpose (``log = self.get_logger``): reported
only where the method itself is used as what it returns (``self.get_logger.info``), tested,
or named alone."""
_FUTURE_MAKERS = frozenset({"call_async", "send_goal_async", "get_result_async",
                            "cancel_goal_async"})
_OK = frozenset({"rclpy.ok", "rclpy.utilities.ok"})
STATEMENT_METHODS = frozenset({
    "cancel", "reset", "shutdown", "try_shutdown", "init", "spin", "spin_once",
    "spin_until_future_complete", "publish", "publish_feedback", "succeed", "abort", "canceled",
    "add_node", "remove_node", "sleep", "wait_for_service", "wait_for_server",
    "declare_parameter", "declare_parameters", "undeclare_parameter", "set_parameters",
    "add_done_callback"})
"""Methods of rclpy's objects and functions of rclpy that code calls for what they do: named
alone as a statement (``self.timer.cancel``), whatever the object, they do nothing."""
_TESTS = (ast.If, ast.While, ast.IfExp, ast.Assert)


def _made(value: ast.expr | None, index: Index) -> str | None:
    """The kind of rclpy object ``value`` makes (a key of :data:`METHODS`), if it is a call
    that makes one; ``none`` for the constant None."""
    if value is not None and is_none(value):
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


def _kind(value: ast.expr, package: Package, tree: ast.Module, index: Index) -> str | None:
    """The kind of rclpy object ``value`` certainly is (a key of :data:`METHODS`)."""
    if isinstance(value, ast.Name) and id(value) in done_callback_futures(tree, index):
        return "future"
    if isinstance(value, ast.Call):
        return _made(value, index)
    cls = receiver_class(value, index) if isinstance(value, ast.Name) else None
    if cls is not None and cls.bases and bases_are_nodes(cls, index) and \
            not any(f.name in METHODS["node"] for f in index.functions):
        return "node"
    values = assigned_values(value, package, tree, index)
    return _agreed([_made(v, i) for v, i in values]) if values else None


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


def _named_alone(node: ast.Attribute, index: Index) -> bool:
    """True for a statement that only names one of :data:`STATEMENT_METHODS` (or a
    ``destroy_*`` method), outside the body and handlers of a ``try`` and a ``with`` block (a
    test expecting the AttributeError); in a ``finally`` or ``else`` block it counts."""
    parent = index.parents.get(id(node))
    if not isinstance(parent, ast.Expr) or not (
            node.attr in STATEMENT_METHODS or node.attr.startswith("destroy_")):
        return False
    child, around = parent, index.parents.get(id(parent))
    while around is not None and not isinstance(around, (*TRIES, ast.With, *FUNCTIONS)):
        child, around = around, index.parents.get(id(around))
    if isinstance(around, TRIES):
        return not any(part is child for part in (*around.body, *around.handlers))
    return not isinstance(around, ast.With)


def _logs_through(node: ast.Attribute, index: Index) -> bool:
    """True for ``<object>.get_logger.info(...)`` in a module defining no ``get_logger``: a
    logging call on the method itself, whatever node it belongs to (not on a module:
    ``rclpy.get_logger`` is PYC004's)."""
    parent = index.parents.get(id(node))
    call = index.parents.get(id(parent))
    return node.attr == "get_logger" and index.qualified(node) is None and \
        isinstance(parent, ast.Attribute) and \
        parent.attr in LEVELS and isinstance(call, ast.Call) and call.func is parent \
        and not index.defines_function("get_logger") and not _stray_self(node.value, index)


def _stray_self(value: ast.expr, index: Index) -> bool:
    """True for ``self`` (or ``self.x``) where no function around binds ``self`` (in a
    module-level ``main()``): the NameError PYC001 reports comes first."""
    while isinstance(value, ast.Attribute):
        value = value.value
    if not isinstance(value, ast.Name) or value.id != "self":
        return False
    function = index.enclosing_function(value)
    while function is not None:
        if "self" in bound_names(function):
            return False
        function = index.enclosing_function(function)
    return True


def _uncalled_methods(package: Package, tree: ast.Module, index: Index
                      ) -> Iterator[tuple[ast.expr, str]]:
    """(node, kind of object) of the methods of :data:`METHODS` taken without a call, and
    ``rclpy.ok`` tested without one (kind ``rclpy``)."""
    wanted = frozenset().union(*METHODS.values())
    for node in index.attributes:
        if node.attr == "ok" and index.qualified(node) in _OK and _tested(node, index):
            yield node, "rclpy"
        if _named_alone(node, index):
            yield node, ""
            continue
        own = _own_method(node, index) if _truth_tested(node, index) else None
        if own is not None:
            yield node, f"`{own}`"
            continue
        if node.attr not in wanted or not _uncalled(node, index):
            continue
        if _logs_through(node, index):
            yield node, "node"
            continue
        kind = _kind(node.value, package, tree, index)
        if kind is not None and node.attr in METHODS.get(kind, ()) and (
                kind not in _ALIASED or _tested(node, index) or
                isinstance(index.parents.get(id(node)), ast.Attribute)):
            yield node, kind
    for name in nodes_of_class(tree, ast.Name):
        assert isinstance(name, ast.Name)
        if name.id == "ok" and index.qualified(name) in _OK and _tested(name, index):
            yield name, "rclpy"


def _truth_tested(node: ast.expr, index: Index) -> bool:
    """True when only ``node``'s truth is used: the test of an ``if``, ``while``, conditional
    expression or ``assert``, also through ``not``, ``and`` and ``or`` (not ``cb = given or
    self.default``, whose value is kept)."""
    child, parent = node, index.parents.get(id(node))
    while isinstance(parent, ast.BoolOp) or \
            isinstance(parent, ast.UnaryOp) and isinstance(parent.op, ast.Not):
        if isinstance(parent, ast.UnaryOp):
            return True
        child, parent = parent, index.parents.get(id(parent))
    return isinstance(parent, _TESTS) and parent.test is child


def _own_method(node: ast.Attribute, index: Index) -> str | None:
    """The name of the class ``node`` (``self.check``, in a plain method of that class, which
    no class of the module extends) is a plain method of: defined with ``def`` in its body,
    undecorated, never assigned on an instance or in the class body otherwise; None for
    anything else."""
    function = index.enclosing_function(node)
    cls = index.parents.get(id(function)) if function is not None else None
    arguments = function.args.posonlyargs + function.args.args if function else []
    if not isinstance(cls, ast.ClassDef) or not arguments or function.decorator_list or \
            not isinstance(node.value, ast.Name) or node.value.id != arguments[0].arg or \
            any(isinstance(b, ast.Name) and b.id == cls.name
                for other in index.classes for b in other.bases):
        return None  # a static or class method's first parameter; a class others extend
    methods = [f for f in cls.body if isinstance(f, FUNCTIONS) and f.name == node.attr]
    bound = [s for s in cls.body if not isinstance(s, FUNCTIONS) and any(
        isinstance(n, ast.Name) and n.id == node.attr for n in descendants(s))]
    stored = any(isinstance(n, ast.Attribute) and n.attr == node.attr and
                 not isinstance(n.ctx, ast.Load) for n in subtree(cls))
    dynamic = any(isinstance(f, FUNCTIONS) and f.name in ("__getattr__", "__getattribute__")
                  for f in cls.body)
    if len(methods) != 1 or methods[0].decorator_list or bound or stored or dynamic:
        return None
    return cls.name


def _message(node: ast.expr, kind: str, index: Index) -> str:
    text = ast.unparse(node)
    if not kind:
        return f"`{text}` names a method without calling it: the statement does nothing"
    what = "a function" if kind == "rclpy" else f"a method of {kind}" \
        if kind.startswith("`") else f"a method of rclpy's {kind}"
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
    `server_is_ready` and `wait_for_server` of an action client, `now` of `get_clock()`, and
    a node's own `get_logger`, `get_clock`, `get_name`, `get_namespace` (only where what it
    returns is used: `self.get_logger.info(...)`; any object's `get_logger` given a logging
    call, `self.node.get_logger.warn(...)`, in a module defining no `get_logger`), taken
    without `()` (not when passed to a call: a callable given on purpose), and `rclpy.ok`
    tested without `()`. A local name or a node's `self.x` counts when every assignment of
    it makes such an object (or None). Also reports a statement that only names a method
    code calls for what it does (`self.timer.cancel`, `node.destroy_node`, `rclpy.shutdown`,
    `rate.sleep`, `publisher.publish`: see the list in the source), on any object, outside
    `with` blocks and the body and handlers of a `try` (in its `finally` block too). And a
    method of the class being defined tested without `()` (`if self.wall_on_right:` in a
    method of the class defining `def wall_on_right(self, scan)`), when the class defines it
    once, undecorated, binds the name nowhere else (no `self.wall_on_right = ...`) and has no
    `__getattr__`.

    ## Why is this bad?
    Without `()` the code has the bound method, not its result: `future.result.sum` raises
    `AttributeError: 'builtin_function_or_method' object has no attribute 'sum'`, and a method
    is always true, so `while rclpy.ok:` never ends and `if future.done:` always passes; a
    method named alone is never run (the timer is never cancelled).

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
