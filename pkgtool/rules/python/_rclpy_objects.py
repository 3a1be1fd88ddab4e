"""The rclpy class an expression's value certainly is (PYC004): what a node's ``create_*``
methods make, its clock and that clock's times, futures of service calls, times, durations,
the executors rclpy provides, a node's parameters, and an action client's goal futures and
goal handles.

A node is ``self`` in a plain method of a class deriving from ``rclpy.node.Node`` alone, or
what ``Node(...)``/``rclpy.create_node(...)`` makes; a future, also the parameter of a done
callback. A local name or ``self.x`` has a class when every value assigned to it
(:func:`~pkgtool.rules.python._assignments.assigned_values`) is of that class, ``None``
placeholders aside (a read of a missing attribute fails on ``None`` too). Anything else is
unknown.
"""

from __future__ import annotations

import ast
from collections.abc import Callable

from pkgtool.model.memo import per_package
from pkgtool.model.package import Package
from pkgtool.rules.node_api import derives_from_node_alone
from pkgtool.rules.python._assignments import (assigned_values, done_callback_futures, is_none,
                                               parameter_annotation, sole)
from pkgtool.rules.python._value_types import receiver_class
from pkgtool.rules.syntax_trees import Index, installed_tree_of

NODE = "rclpy.node.Node"
TIME, DURATION = "rclpy.time.Time", "rclpy.duration.Duration"
FUTURE = "rclpy.task.Future"
EXECUTORS = ("rclpy.executors.SingleThreadedExecutor", "rclpy.executors.MultiThreadedExecutor")
ACTIONS = {f"rclpy.action{where}.Action{kind}": f"rclpy.action.{kind.lower()}.Action{kind}"
           for kind in ("Client", "Server") for where in ("", f".{kind.lower()}")}
"""rclpy's action client and server classes by every name they are imported by."""
CLOCK = "rclpy.clock.ROSClock"
"""A node's clock (a ``Clock`` made for ROS time is one too: the class with most)."""
ACTION_CLIENT = "rclpy.action.client.ActionClient"
GOAL_HANDLE = "rclpy.action.client.ClientGoalHandle"
PARAMETER = "rclpy.parameter.Parameter"
GOAL_FUTURE = f"{FUTURE}<ClientGoalHandle>"
"""The future ``ActionClient.send_goal_async`` returns: a ``Future`` whose result is the goal's
``ClientGoalHandle`` (the one future whose result's class is certain)."""
_MADE_BY = {
    (NODE, "create_publisher"): "rclpy.publisher.Publisher",
    (NODE, "create_subscription"): "rclpy.subscription.Subscription",
    (NODE, "create_timer"): "rclpy.timer.Timer", (NODE, "create_rate"): "rclpy.timer.Rate",
    (NODE, "create_client"): "rclpy.client.Client",
    (NODE, "create_service"): "rclpy.service.Service", (NODE, "get_clock"): CLOCK,
    (CLOCK, "now"): TIME, ("rclpy.client.Client", "call_async"): FUTURE,
    (ACTION_CLIENT, "send_goal_async"): GOAL_FUTURE, (GOAL_FUTURE, "result"): GOAL_HANDLE,
    (NODE, "declare_parameter"): PARAMETER, (NODE, "get_parameter"): PARAMETER,
    (NODE, "get_parameter_or"): PARAMETER,
    (GOAL_HANDLE, "get_result_async"): FUTURE, (GOAL_HANDLE, "cancel_goal_async"): FUTURE,
}
"""(class, method) -> the class of what the method returns (Humble to Rolling)."""
_MAKERS = frozenset(method for _, method in _MADE_BY)
"""The methods whose result may have a class: the receiver of any other is not asked for."""
_CONSTRUCTED = {NODE: NODE, "rclpy.create_node": NODE, TIME: TIME, DURATION: DURATION,
                "rclpy.time.Duration": DURATION, "rclpy.clock.Clock": CLOCK, CLOCK: CLOCK,
                FUTURE: FUTURE, PARAMETER: PARAMETER,
                f"{TIME}.from_msg": TIME, f"{DURATION}.from_msg": DURATION,
                **{executor: executor for executor in EXECUTORS}, **ACTIONS}
"""What calling an rclpy class or factory makes."""
_ARITHMETIC = {(TIME, ast.Sub, TIME): DURATION, (TIME, ast.Sub, DURATION): TIME,
               (TIME, ast.Add, DURATION): TIME, (DURATION, ast.Add, TIME): TIME}
_DEPTH = 8
"""How many bindings deep a value is followed (``t = clock.now()`` with ``clock = ...``)."""
_cut = [0]
"""How many times :func:`object_class` stopped at :data:`_DEPTH`: a class not found when it
did is not final (the same name asked for less deep may have one)."""


def object_class(value: ast.expr, package: Package, tree: ast.Module, index: Index,
                 depth: int = 0) -> str | None:
    """The rclpy class ``value`` (in ``tree``) certainly is an instance of, or None."""
    if depth > _DEPTH:
        _cut[0] += 1
        return None
    if isinstance(value, ast.Call):
        func = value.func
        if isinstance(func, ast.Attribute) and func.attr in _MAKERS:
            receiver = object_class(func.value, package, tree, index, depth + 1)
            made = _MADE_BY.get((receiver or "", func.attr))
            own = receiver == NODE and index.defines_function(func.attr)  # the class's method
            if made is not None and not own:
                return made
        return _CONSTRUCTED.get(index.qualified(func) or "") \
            if isinstance(func, (ast.Name, ast.Attribute)) else None
    if isinstance(value, ast.BinOp):
        left = object_class(value.left, package, tree, index, depth + 1)
        right = object_class(value.right, package, tree, index, depth + 1) if left else None
        return _ARITHMETIC.get((left or "", type(value.op), right or ""))
    if isinstance(value, ast.Name):
        if value.id in index.aliases:
            return None  # bound by imports alone: a module or class, never an instance
        registered = done_callback_futures(tree, index).get(id(value))
        if registered:  # a done callback's parameter: the future, when it is rclpy's
            return sole({object_class(v, package, tree, index, depth + 1) for v in registered})
        if depth and _node_self(value, index):  # a receiver (reads on a node are not ours)
            return NODE
        function = index.enclosing_function(value, through_lambdas=False)
        if function is None:
            return None
        return _remembered(package, (id(function), value.id), depth, lambda: (
            _annotated_class(value.id, function, index) or
            _assigned_class(value, package, tree, index, depth)))
    if isinstance(value, ast.Attribute) and isinstance(value.value, ast.Name):
        cls = receiver_class(value.value, index)
        if cls is None:
            return None
        return _remembered(package, (id(cls), value.attr), depth,
                           lambda: _assigned_class(value, package, tree, index, depth))
    return None


def _remembered(package: Package, key: tuple[int, str], depth: int,
                find: Callable[[], str | None]) -> str | None:
    """The class of a local name or ``self.x`` (``key``: see :func:`_attribute_classes`) asked
    for ``depth`` bindings deep: found once, and again only when asked for less deep than a
    search that stopped at :data:`_DEPTH` (at most :data:`_DEPTH` searches per key)."""
    known = _attribute_classes(package)
    entry = known.get(key)
    if entry is not None and (entry[0] is not None or not entry[2] or entry[1] <= depth):
        return entry[0]
    cuts = _cut[0]
    found = find()
    known[key] = (found, depth, _cut[0] != cuts)
    return found


def _annotated_class(name: str, function: ast.FunctionDef | ast.AsyncFunctionDef,
                     index: Index) -> str | None:
    """The rclpy class a parameter ``name`` of ``function`` is annotated with (``future:
    Future``), when nothing in the function rebinds it."""
    note = parameter_annotation(function, name)
    if not isinstance(note, (ast.Name, ast.Attribute)):
        return None
    made = _CONSTRUCTED.get(index.qualified(note) or "")
    return made if made in (TIME, DURATION, FUTURE, CLOCK, *EXECUTORS, *ACTIONS.values()) \
        else None


def _assigned_class(value: ast.Name | ast.Attribute, package: Package, tree: ast.Module,
                    index: Index, depth: int) -> str | None:
    """The one class of every value assigned to ``value`` (``None`` placeholders aside)."""
    assigned = assigned_values(value, package, tree, index)
    trees = installed_tree_of(package) if assigned else {}
    return sole({object_class(v, package, trees[id(i)], i, depth + 1)
                 for v, i in assigned or () if not is_none(v)})


@per_package
def _attribute_classes(package: Package) -> dict[tuple[int, str], tuple[str | None, int, bool]]:
    """The class of ``self.x`` by (id of the class whose method reads it, ``x``), and of a
    local name by (id of its function, name), filled as rules ask (every read of ``self.x``
    in one class, of a name in one function, has the same); with the depth it was searched
    at and whether that search stopped at :data:`_DEPTH`."""
    return {}


def _node_self(name: ast.Name, index: Index) -> bool:
    """True for ``self`` in a plain method of a class deriving from rclpy's Node alone."""
    cls = receiver_class(name, index)
    return cls is not None and derives_from_node_alone(cls, index)


def table_class(cls: str) -> str:
    """The class whose attributes ``cls`` has (a :data:`GOAL_FUTURE` is a ``Future``)."""
    return cls.partition("<")[0]
