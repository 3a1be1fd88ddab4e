"""PYC029: an rclpy call given a keyword its function does not take (``timeout=``)."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rclpy_signatures import methods, parameters_of
from pkgtool.knowledge.rosdistro import typo_of
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import (PARAMETERS, derives_from_node_alone, node_api_calls,
                                    node_constructions, not_from_rclpy)
from pkgtool.rules.python._assignments import assigned_values
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, installed_tree_of, installed_trees

WRONG_KEYWORDS: dict[str, dict[str, str]] = {
    "wait_for_service": {"timeout": "timeout_sec"},
    "wait_for_server": {"timeout": "timeout_sec"},
    "spin_once": {"timeout": "timeout_sec"},
    "spin_until_future_complete": {"timeout": "timeout_sec"},
    "create_timer": {"period": "timer_period_sec", "timer_period": "timer_period_sec",
                     "period_sec": "timer_period_sec"},
    "create_publisher": {"queue_size": "qos_profile"},
    "create_subscription": {"queue_size": "qos_profile"},
    "declare_parameter": {"default": "value", "default_value": "value"},
    "get_parameter_or": {"default": "alternative_value", "default_value": "alternative_value"},
}
"""rclpy methods and functions (Foxy to Rolling), the keywords people give them that they do
not take, and the keyword meant."""
NODE_KEYWORDS = {"name": "node_name"}
"""The same for ``Node.__init__`` and ``rclpy.create_node``."""


def _wrong(call: ast.Call, table: dict[str, str]) -> Iterator[tuple[ast.keyword, str]]:
    for keyword in call.keywords:
        if keyword.arg in table:
            yield keyword, table[keyword.arg]


def _given_twice(call: ast.Call, parameters: tuple[str, ...]) -> ast.keyword | None:
    """The first keyword of ``call`` naming a parameter its positional arguments fill."""
    if any(isinstance(a, ast.Starred) for a in call.args):
        return None
    filled = set(parameters[:len(call.args)])
    return next((k for k in call.keywords if k.arg in filled), None)


@rule("PYC029", "unexpected-rclpy-keyword", Severity.ERROR,
      fix="Use the keyword rclpy's function takes (see the message)")
def unexpected_rclpy_keyword(package: Package) -> Iterator[Hit]:
    """An rclpy function is called with a keyword it does not take.

    ## What it does
    Reports keywords that rclpy's functions do not have, where people reach for a near
    name: `timeout=` for `timeout_sec=` (`wait_for_service`, `wait_for_server`, `spin_once`,
    `spin_until_future_complete`), `period=` for `timer_period_sec=` (`create_timer`),
    `queue_size=` (rospy's) for `qos_profile=` (`create_publisher`, `create_subscription`),
    `default=` or `default_value=` for `value=` (`declare_parameter`) and for
    `alternative_value=` (`get_parameter_or`), and `name=` for `node_name=` (Node
    constructors: `super().__init__(...)` in a Node subclass, `Node(...)`,
    `rclpy.create_node(...)`). Also a keyword naming a parameter that the positional
    arguments already fill (`create_subscription(Twist, 'cmd', self.cb, 10, callback=...)`)
    of `create_publisher`, `create_subscription`, `create_service` and `create_client`. And
    any keyword that none of Humble's, Jazzy's and Rolling's rclpy takes, with the parameter
    a typo away when there is one (`callback_grup=`, `timeot_sec=`), in the calls of a
    generated table: a node's `create_*`, `declare_parameter(s)` and `get_parameter_or`, a
    client's `call_async` and `wait_for_service`, an action client's `send_goal_async` and
    `wait_for_server`, `rclpy.init`, `spin`, `spin_once`, `spin_until_future_complete`,
    node constructors, `ActionServer`, `ActionClient` and the executors. As for the other
    rclpy checks, only modules importing rclpy are looked at, and not when the package
    defines a function of the same name (a wrapper of its own), nor for methods called on a
    name or `self.x` only ever assigned what another library makes (flexbe's
    `ProxyServiceCaller(...)`, whose `call_async` takes `wait_duration=`).

    ## Why is this bad?
    Python raises `TypeError: ... got an unexpected keyword argument 'timeout'` when the line
    runs: at start-up for a node's constructor, and in the middle of a run (in a callback,
    where the executor logs it and the node stops doing its job) for the others.

    ## Example
    ```python
    while not self.client.wait_for_service(timeout=1.0):
        self.get_logger().info('waiting for the service')
    ```

    ## Use instead
    ```python
    while not self.client.wait_for_service(timeout_sec=1.0):
        self.get_logger().info('waiting for the service')
    ```
    """
    defined = {function.name for _, _, index in installed_trees(package)
               for function in index.functions}
    trees = installed_tree_of(package)
    for module, call, method, index in node_api_calls(package, WRONG_KEYWORDS):
        for keyword, meant in _wrong(call, WRONG_KEYWORDS[method]) if method not in defined \
                and not _wrapper(call, package, trees[id(index)], index) else ():
            yield Hit(Span(module.path, keyword.lineno, keyword.col_offset + 1),
                      f"`{method}()` has no `{keyword.arg}` argument: it raises TypeError",
                      f"Write `{meant}=`")
    for module, call, method, _ in node_api_calls(package, PARAMETERS):
        twice = _given_twice(call, PARAMETERS[method]) if method not in defined else None
        if twice is not None:
            yield Hit(Span(module.path, twice.lineno, twice.col_offset + 1),
                      f"`{method}()` gets `{twice.arg}` twice, by position and as "
                      f"`{twice.arg}=`: it raises TypeError (multiple values for argument)",
                      f"Remove `{twice.arg}=` or the positional argument")
    for module, _, index in installed_trees(package):
        if not any(i.top_level == "rclpy" for i in module.imports):
            continue
        for call in node_constructions(index):
            for keyword, meant in _wrong(call, NODE_KEYWORDS):
                yield Hit(Span(module.path, keyword.lineno, keyword.col_offset + 1),
                          f"A node's constructor has no `{keyword.arg}` argument: it raises "
                          "TypeError", f"Write `{meant}=`")
            if _plain_node(call, index):
                yield from _unknown(module.path, call, "rclpy.node.Node",
                                    "A node's constructor", NODE_KEYWORDS)
        for call in index.calls:
            named = index.qualified(call.func) if isinstance(call.func, (ast.Name,
                                                                         ast.Attribute)) else None
            if named and named.startswith("rclpy.") and named not in _NODES:
                yield from _unknown(module.path, call, named, f"`{named.rpartition('.')[2]}()`",
                                    WRONG_KEYWORDS.get(named.rpartition(".")[2], {}))
    for module, call, method, index in node_api_calls(package, methods()):
        if method not in defined and not _wrapper(call, package, trees[id(index)], index):
            yield from _unknown(module.path, call, method, f"`{method}()`",
                                WRONG_KEYWORDS.get(method, {}))


def _wrapper(call: ast.Call, package: Package, tree: ast.Module, index: Index) -> bool:
    """True when the receiver of the method ``call`` (a local name or ``self.x``) only ever
    holds what code from outside rclpy makes: another library's object with a method of the
    same name (flexbe's ``ProxyServiceCaller().call_async(topic, request, wait_duration=)``)."""
    receiver = call.func.value if isinstance(call.func, ast.Attribute) else None
    assigned = assigned_values(receiver, package, tree, index) if receiver is not None else None
    return bool(assigned) and all(not_from_rclpy(value, where) for value, where in assigned)


_NODES = ("rclpy.node.Node", "rclpy.create_node")
"""What makes a plain rclpy node (``Node.__init__``'s keywords)."""


def _plain_node(call: ast.Call, index: Index) -> bool:
    """True for ``Node(...)``, ``rclpy.create_node(...)`` and ``super().__init__(...)`` in a
    class deriving from ``rclpy.node.Node`` alone (a lifecycle node takes more keywords)."""
    if isinstance(call.func, (ast.Name, ast.Attribute)) and index.qualified(call.func) in _NODES:
        return True
    cls = index.enclosing_class(call)
    return cls is not None and derives_from_node_alone(cls, index)


def _unknown(path: str, call: ast.Call, name: str, shown: str, curated: dict[str, str]
             ) -> Iterator[Hit]:
    """A hit for each keyword of ``call`` that rclpy's ``name`` takes on no distribution,
    except those ``curated`` reports with its own words."""
    parameters = parameters_of(name)
    if parameters is None or "**" in parameters:
        return
    for keyword in call.keywords:
        if keyword.arg is None or keyword.arg in parameters or keyword.arg in curated:
            continue
        meant = typo_of(keyword.arg, parameters)
        hint = f" (did you mean `{meant}`?)" if meant else ""
        yield Hit(Span(path, keyword.lineno, keyword.col_offset + 1),
                  f"{shown} has no `{keyword.arg}` argument{hint}: it raises TypeError",
                  f"Write `{meant}=`" if meant else
                  f"Use one of its parameters: {', '.join(sorted(parameters))}")
