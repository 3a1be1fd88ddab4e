"""PYC092: a node's ``__init__`` waits in a loop for what only its callbacks set."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import subtree
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.call_graph import reached
from pkgtool.rules.node_api import derives_from_node_alone
from pkgtool.rules.python._init_callbacks import (Method, Methods, attribute_setters,
                                                  called_methods, is_self, methods_of,
                                                  registered_callbacks)
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import FUNCTIONS, Index, installed_trees

_RUNS_CALLBACKS = ("spin", "wait_for_message", "xecutor", "hread", "add_node")
"""Parts of names (and keyword arguments) that may run the node's callbacks meanwhile
(``rclpy.spin_once(self)``, ``wait_for_message``, an executor, a thread spinning the node,
``TransformListener(buffer, self, spin_thread=True)``, ``executor.add_node(self)``)."""


@rule("PYC092", "wait-without-spinning", Severity.ERROR,
      fix="Let the callback do the work (start a timer, act on the first message), or spin "
          "while waiting: `while not self.ready: rclpy.spin_once(self)`")
def wait_without_spinning(package: Package) -> Iterator[Hit]:
    """A node's `__init__` waits in a loop for an attribute only its callbacks set.

    ## What it does
    In a class deriving from rclpy's `Node` alone (no decorator, not extended in the
    module), looks at the `while` loops of `__init__` and of the methods it calls. Reports
    a loop whose test reads `self.x` (`while not self.ready`, `while self.pose is None`) and
    calls nothing but `len`, when `x` is assigned only by callbacks `__init__` registers
    (timer, subscription or service callbacks that nothing else calls) and, before that,
    only with a value that keeps the loop going (`self.ready = False`, `self.pose = None`),
    when nothing can run callbacks meanwhile (no `spin`, `spin_once`, `wait_for_message`,
    executor, `add_node` or thread, nor `spin_thread=`, in `__init__`, the methods it calls
    or the module's functions they call) and nothing in the loop leaves it (no `break`,
    `return` or `raise`).

    ## Why is this bad?
    Callbacks run only when an executor spins the node, and nothing spins a node before its
    constructor returns (`rclpy.spin(Talker())` comes after). The loop waits for a value
    nothing can set: `ros2 run` hangs forever at start-up, printing nothing, and the node
    never appears in `ros2 node list`. rospy's habit of waiting for a first message in the
    constructor works in ROS 1 only, where callbacks run on threads of their own.

    ## Example
    ```python
    def __init__(self):
        super().__init__('follower')
        self.pose = None
        self.create_subscription(Pose, 'pose', self.on_pose, 10)
        while self.pose is None:
            time.sleep(0.1)

    def on_pose(self, msg):
        self.pose = msg
    ```

    ## Use instead
    ```python
    def __init__(self):
        super().__init__('follower')
        self.pose = None
        self.create_subscription(Pose, 'pose', self.on_pose, 10)
        while self.pose is None:
            rclpy.spin_once(self, timeout_sec=0.1)
    ```
    """
    for module, tree, index in installed_trees(package):
        extended = {b.id for c in index.classes for b in c.bases if isinstance(b, ast.Name)}
        for cls in index.classes:
            if derives_from_node_alone(cls, index) and cls.name not in extended and \
                    not cls.decorator_list:
                for loop, method, attr, setters in _endless_waits(cls, index):
                    through = "" if method == "__init__" else \
                        f" (`__init__` runs it, through `{method}`)"
                    yield Hit(Span(module.path, loop.lineno, loop.col_offset + 1),
                              f"This loop{through} waits for `self.{attr}`, which only the "
                              f"callback `{setters}` sets; callbacks run only once the node "
                              "spins, after its constructor returns: the node hangs here "
                              "forever")


def _endless_waits(cls: ast.ClassDef, index: Index
                   ) -> Iterator[tuple[ast.While, str, str, str]]:
    """(loop, its method, attribute, its setting callbacks) for each loop of ``cls``'s
    ``__init__`` (or the methods it calls) that waits for an attribute only registered
    callbacks set."""
    methods = methods_of(cls)
    init = methods.get("__init__")
    if init is None:
        return
    run = (init, *called_methods(init, methods))
    helpers = _module_functions_called(run, index)
    if any(_may_run_callbacks(node) for function in (*run, *helpers)
           for node in subtree(function)):
        return  # a thread or an executor spinning the node meanwhile
    callbacks = set().union(*registered_callbacks(init, methods).values()) - \
        {method.name for method in run}  # a callback __init__ calls itself may set it
    setters = attribute_setters(cls, index, methods, calls_unknown=False)
    for method in run:
        for loop in (n for n in subtree(method) if isinstance(n, ast.While) and
                     index.enclosing_function(n) is method):
            reads = {n.attr for n in subtree(loop.test) if isinstance(n, ast.Attribute) and
                     is_self(n.value, method)}
            if not reads or not _plain_test(loop.test) or not _stays(loop):
                continue
            for attr in sorted(reads):
                where = setters.get(attr, set())
                values = _first_values(attr, where - callbacks, methods, loop, method) \
                    if where & callbacks else None
                if values and all(_holds(loop.test, attr, value) for value in values):
                    yield loop, method.name, attr, "`, `".join(sorted(where & callbacks))
                    break


def _plain_test(test: ast.expr) -> bool:
    """True when the loop's test calls nothing but ``len`` and ``bool``."""
    return all(isinstance(n.func, ast.Name) and n.func.id in ("len", "bool")
               for n in subtree(test) if isinstance(n, ast.Call))


def _module_functions_called(run: tuple[Method, ...], index: Index) -> list[Method]:
    """The module's own functions the methods of ``run`` call by name, and those they
    call (``wait_until_ready(self)`` may spin the node)."""
    defined = {f.name: f for f in index.functions
               if index.enclosing_class(f) is None and index.enclosing_function(f) is None}
    return reached(run, lambda call, _: defined.get(call.func.id)
                   if isinstance(call.func, ast.Name) else None)


def _may_run_callbacks(node: ast.AST) -> bool:
    """True for a name, attribute or keyword argument that may run the node's callbacks
    (see _RUNS_CALLBACKS)."""
    name = node.attr if isinstance(node, ast.Attribute) else \
        node.id if isinstance(node, ast.Name) else \
        node.arg or "" if isinstance(node, ast.keyword) else ""
    return any(part in name for part in _RUNS_CALLBACKS)


def _stays(loop: ast.While) -> bool:
    """True when nothing in the loop may leave it."""
    return not loop.orelse and not any(
        isinstance(node, (ast.Break, ast.Return, ast.Raise, ast.Yield, ast.YieldFrom,
                          ast.Await, ast.Try, ast.Lambda, *FUNCTIONS))
        for node in subtree(loop))


_NOT_CONSTANT = object()
"""An assigned value other than a constant or an empty display."""
_UNASSIGNED = object()
"""What a statement assigning nothing assigns."""


def _first_values(attr: str, others: set[str], methods: Methods, loop: ast.While,
                  method: Method) -> list[object] | None:
    """The values ``__init__`` (and the loop's method) assign ``self.<attr>`` before the
    loop, when the callbacks are the only other methods assigning it and each of those is a
    constant or an empty list, dict or set (as Python values); None otherwise."""
    values: list[object] = []
    for name in others:
        if name not in ("__init__", method.name):
            return None
        for node in subtree(methods[name]):
            value = _assigned(node, attr, methods[name])
            if value is _UNASSIGNED:
                continue
            if value is _NOT_CONSTANT or not _before(node, loop, methods[name], method):
                return None
            values.append(value)
    return values or None


def _assigned(node: ast.AST, attr: str, method: Method) -> object:
    """The value ``node`` assigns ``self.<attr>``, as a Python value; :data:`_UNASSIGNED`
    when it assigns none; :data:`_NOT_CONSTANT` for anything but a constant or an empty
    display."""
    if isinstance(node, ast.AugAssign) and isinstance(node.target, ast.Attribute) and \
            node.target.attr == attr and is_self(node.target.value, method):
        return _NOT_CONSTANT
    if not isinstance(node, (ast.Assign, ast.AnnAssign)):
        return _UNASSIGNED
    targets = node.targets if isinstance(node, ast.Assign) else [node.target]
    if not any(isinstance(t, ast.Attribute) and t.attr == attr and is_self(t.value, method)
               for t in (n for target in targets for n in subtree(target))):
        return _UNASSIGNED
    value = node.value
    if len(targets) != 1 or not isinstance(targets[0], ast.Attribute) or value is None:
        return _NOT_CONSTANT
    if isinstance(value, ast.Constant):
        return value.value
    if isinstance(value, (ast.List, ast.Set)) and not value.elts:
        return []
    if isinstance(value, ast.Dict) and not value.keys:
        return {}
    return _NOT_CONSTANT


def _before(node: ast.AST, loop: ast.While, owner: Method, method: Method) -> bool:
    """True when the assignment ``node`` of ``owner`` comes before ``loop`` of ``method`` (in
    another method: ``__init__``, which calls the loop's method)."""
    return owner is not method or \
        (node.lineno, node.col_offset) < (loop.lineno, loop.col_offset)


def _holds(test: ast.expr, attr: str, value: object) -> bool:
    """True when ``test`` is certainly true while ``self.<attr>`` is ``value``: ``not
    self.x``, ``self.x is None``, ``self.x == c``, ``self.x != c``, ``len(self.x) == 0``,
    ``not len(self.x)``, or ``or`` of such tests (one suffices)."""
    if isinstance(test, ast.BoolOp) and isinstance(test.op, ast.Or):
        return any(_holds(part, attr, value) for part in test.values)
    if isinstance(test, ast.UnaryOp) and isinstance(test.op, ast.Not):
        seen = _seen(test.operand, attr, value)
        return seen is not _NOT_CONSTANT and not seen
    if not (isinstance(test, ast.Compare) and len(test.ops) == 1 and
            isinstance(test.comparators[0], ast.Constant)):
        return False
    seen, other, op = _seen(test.left, attr, value), test.comparators[0].value, test.ops[0]
    if seen is _NOT_CONSTANT:
        return False
    return isinstance(op, ast.Is) and seen is other or \
        isinstance(op, ast.IsNot) and seen is not other or \
        isinstance(op, ast.Eq) and seen == other or isinstance(op, ast.NotEq) and seen != other


def _seen(read: ast.expr, attr: str, value: object) -> object:
    """What ``read`` gives while ``self.<attr>`` is ``value``: for ``self.<attr>`` the value,
    for ``len(self.<attr>)`` its length; :data:`_NOT_CONSTANT` for anything else."""
    if isinstance(read, ast.Call) and isinstance(read.func, ast.Name) and \
            read.func.id == "len" and len(read.args) == 1:
        return len(value) if isinstance(value, (str, list, dict)) and \
            _seen(read.args[0], attr, value) is value else _NOT_CONSTANT
    return value if isinstance(read, ast.Attribute) and read.attr == attr and \
        isinstance(read.value, ast.Name) else _NOT_CONSTANT
