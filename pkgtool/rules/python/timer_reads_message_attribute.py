"""PYC090: a timer callback reads an attribute only a subscription callback sets."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rclpy_node import NODE_ATTRIBUTES
from pkgtool.model.ast_nodes import TRIES, descendants, nodes_of_class, subtree
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import derives_from_node_alone
from pkgtool.rules.python._attribute_guards import dynamic_attributes, guarded, probed_names
from pkgtool.rules.python._certain_code import certain_parts
from pkgtool.rules.python._init_callbacks import (attribute_setters, called_methods, is_self,
                                                  methods_of, registered_callbacks)
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import FUNCTIONS, Index, installed_trees

_WAITS = ("spin", "wait")
"""Parts of the names of calls in ``__init__`` that may run callbacks or wait for a message
before the timer starts (``rclpy.spin_once(self)``, ``wait_for_message``)."""


@rule("PYC090", "timer-reads-message-attribute", Severity.WARNING,
      fix="Give the attribute a value in `__init__` (`self.latest = None`) and have the timer "
          "callback return while it has none")
def timer_reads_message_attribute(package: Package) -> Iterator[Hit]:
    """A timer callback reads an attribute that only a subscription callback assigns.

    ## What it does
    In a class deriving from rclpy's `Node` alone (no decorator, not extended in the
    module), whose `__init__` registers a timer callback and a subscription callback (its
    own methods) and waits for nothing (no `spin`, no `wait_for_message`, also in the methods
    it calls), reports a read of `self.x` in the timer callback that certainly runs (before
    any `try`, `match` or branch that may return) when `x` is assigned only in subscription
    callbacks that nothing else calls: not in `__init__`, another method or outside the
    class (`node.x = ...` in `main()`), not a class attribute, a method, nor an attribute of
    `Node`. Timers made with `autostart=` or cancelled in `__init__` (a callback starts them
    later) are left alone, and so are reads the module guards (`hasattr(self, 'x')`, inside
    `try: ... except AttributeError`).

    ## Why is this bad?
    A timer starts counting when it is made; a subscription gets its first message only when
    a publisher sends one. When the timer fires first (the sensor, the bag or the simulator
    is not up yet, or the period is short), `self.x` does not exist and the node dies with
    `AttributeError` before its first message.

    ## Example
    ```python
    def __init__(self):
        super().__init__('nearest')
        self.create_subscription(LaserScan, 'scan', self.on_scan, 10)
        self.create_timer(0.1, self.on_timer)

    def on_scan(self, msg):
        self.nearest = min(msg.ranges)

    def on_timer(self):
        self.get_logger().info(f'{self.nearest:.2f} m')
    ```

    ## Use instead
    ```python
    def __init__(self):
        super().__init__('nearest')
        self.nearest = None
        self.create_subscription(LaserScan, 'scan', self.on_scan, 10)
        self.create_timer(0.1, self.on_timer)

    def on_timer(self):
        if self.nearest is None:
            return
        self.get_logger().info(f'{self.nearest:.2f} m')
    ```
    """
    for module, tree, index in installed_trees(package):
        if dynamic_attributes(tree):
            continue
        probed = probed_names(index)
        extended = {b.id for c in index.classes for b in c.bases if isinstance(b, ast.Name)}
        in_classes = {id(n) for cls in index.classes for n in subtree(cls)}
        elsewhere = {n.attr for n in nodes_of_class(tree, ast.Attribute)
                     if isinstance(n, ast.Attribute) and not isinstance(n.ctx, ast.Load) and
                     id(n) not in in_classes}  # `node.x = ...` in main()
        for cls in index.classes:
            if derives_from_node_alone(cls, index) and cls.name not in extended and \
                    not cls.decorator_list:
                for node, timer, setters in _early_reads(cls, index, probed, elsewhere):
                    yield Hit(Span(module.path, node.lineno, node.col_offset + 1),
                              f"`self.{node.attr}` is read by the timer callback `{timer}` "
                              f"but set only by the subscription callback `{setters}`: when "
                              "the timer fires before the first message, AttributeError "
                              "stops the node")


def _early_reads(cls: ast.ClassDef, index: Index, probed: frozenset[str],
                 elsewhere: set[str]) -> Iterator[tuple[ast.Attribute, str, str]]:
    """(read, timer callback, subscription callbacks) for each attribute a timer callback of
    ``cls`` reads that only its subscription callbacks set (none of ``elsewhere``: assigned
    outside the class, ``node.latest = ...`` in ``main()``)."""
    methods = methods_of(cls)
    init = methods.get("__init__")
    if init is None or any(_waits(f) for f in (init, *called_methods(init, methods))):
        return
    callbacks = registered_callbacks(init, methods)
    timers = callbacks["create_timer"] - callbacks["create_subscription"]
    setters = attribute_setters(cls, index, methods)
    own = {n.id for n in _class_level_names(cls)} | set(methods) | NODE_ATTRIBUTES | elsewhere
    for timer in sorted(timers):
        seen: set[str] = set()
        for node in _certain_reads(methods[timer]):
            where = setters.get(node.attr)
            if node.attr in seen or node.attr in own or not where or \
                    not where <= callbacks["create_subscription"] or \
                    guarded(node, index, probed):
                continue
            seen.add(node.attr)
            yield node, timer, "`, `".join(sorted(where))


def _waits(init: ast.FunctionDef | ast.AsyncFunctionDef) -> bool:
    """True when ``__init__`` (or a method it calls) calls something that may run callbacks
    or wait for messages."""
    return any(isinstance(n, ast.Call) and any(
        w in (n.func.attr if isinstance(n.func, ast.Attribute) else
              n.func.id if isinstance(n.func, ast.Name) else "") for w in _WAITS)
        for n in subtree(init))


def _class_level_names(cls: ast.ClassDef) -> Iterator[ast.Name]:
    """The names the class body itself binds (class attributes)."""
    for statement in cls.body:
        targets = statement.targets if isinstance(statement, ast.Assign) else \
            [statement.target] if isinstance(statement, (ast.AnnAssign, ast.AugAssign)) else []
        yield from (n for target in targets for n in descendants(target)
                    if isinstance(n, ast.Name))


def _certain_reads(function: ast.FunctionDef | ast.AsyncFunctionDef
                   ) -> Iterator[ast.Attribute]:
    """The ``self.x`` reads of ``function`` that run every time it does: what Python
    certainly evaluates of its statements (:func:`certain_parts`) in order up to the first
    ``try``, ``match``, ``with``, loop body or branch that may return or raise (a branch's
    test and a loop's iterable still run)."""
    for statement in function.body:
        if isinstance(statement, (*TRIES, *FUNCTIONS, ast.ClassDef, ast.Match, ast.With,
                                  ast.AsyncWith)):
            return
        yield from (part for part in certain_parts(statement)
                    if isinstance(part, ast.Attribute) and isinstance(part.ctx, ast.Load) and
                    is_self(part.value, function))
        if isinstance(statement, (ast.For, ast.AsyncFor)) or \
                isinstance(statement, (ast.If, ast.While)) and any(
                    isinstance(n, (ast.Return, ast.Raise, ast.Break, ast.Continue))
                    for n in descendants(statement)):
            return
