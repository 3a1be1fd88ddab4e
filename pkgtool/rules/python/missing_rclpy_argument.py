"""PYC049: a node's create_* or parameter method called without an argument it requires."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rclpy_node import NODE_ATTRIBUTES
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import (PARAMETERS, argument, derives_from_node_alone,
                                    node_api_calls, swapped_argument, unpacks)
from pkgtool.rules.python._own_callees import rebound_around
from pkgtool.rules.python._package_classes import package_class, package_classes
from pkgtool.rules.registry import rule
from pkgtool.rules.scopes import scope_bindings
from pkgtool.rules.syntax_trees import Index, installed_trees

REQUIRED = {**PARAMETERS,
            "create_timer": ("timer_period_sec", "callback"),
            "create_rate": ("frequency",),
            "declare_parameter": ("name",),
            "get_parameter": ("name",)}
"""rclpy ``Node`` methods (Humble to Rolling) and their required parameters, in order."""
_ORDERED = frozenset({*PARAMETERS, "create_timer"})
"""The methods PYC030 checks the order of the arguments of."""


@rule("PYC049", "missing-rclpy-argument", Severity.ERROR,
      fix="Pass every argument the method requires: `self.create_timer(0.5, self.tick)`")
def missing_rclpy_argument(package: Package) -> Iterator[Hit]:
    """A node's `create_*` or parameter method is called without an argument it requires.

    ## What it does
    Reports `create_timer`, `create_publisher`, `create_subscription`, `create_service`,
    `create_client`, `create_rate`, `declare_parameter` and `get_parameter` calls on a node
    that leave out a required parameter other than `qos_profile` (PYC007 reports that one):
    `self.create_timer(0.5)` without its callback, `self.create_service(Trigger,
    self.on_reset)` without the service name. Calls passing `*args` or `**kwargs`, and
    modules defining a method of the same name, are not checked, nor calls whose arguments
    are out of order (PYC030 reports them). Also reports a method of rclpy's `Node` called
    on a class, with no node: `Node.destroy_node()`, or `Talker.destroy_node()` for a class
    of the package deriving from `Node` that does not define the method (its `self` is
    missing; a property is not callable either).

    ## Why is this bad?
    Python raises `TypeError: create_timer() missing 1 required positional argument:
    'callback'` when the line runs, usually in the node's constructor: the node never
    starts.

    ## Example
    ```python
    self.timer = self.create_timer(0.5)
    ```

    ## Use instead
    ```python
    self.timer = self.create_timer(0.5, self.tick)
    ```
    """
    for module, call, method, index in node_api_calls(package, REQUIRED):
        parameters = REQUIRED[method]
        missing = [p for p in parameters if p != "qos_profile" and
                   argument(call, parameters, p) is None]
        ordered = method in _ORDERED and swapped_argument(call, method, index) is not None
        if missing and not unpacks(call) and not ordered:  # PYC030 reports the order
            names = " and ".join(f"`{p}`" for p in missing)
            yield Hit(Span(module.path, call.lineno, call.col_offset + 1),
                      f"`{ast.unparse(call)}` leaves out {names}, which `{method}()` requires: "
                      f"Python raises TypeError")
    yield from _called_on_the_class(package)


_NODE = "rclpy.node.Node"


def _called_on_the_class(package: Package) -> Iterator[Hit]:
    """``Node.destroy_node()``: an attribute of rclpy's ``Node`` called on the class itself
    (or on a package class deriving from it alone that does not define it), with nothing."""
    for module, _, index in installed_trees(package):
        for call in index.calls:
            func = call.func
            if isinstance(func, ast.Attribute) and func.attr in NODE_ATTRIBUTES and \
                    not func.attr.startswith("_") and not call.args and not call.keywords and \
                    _is_node_class(func.value, func.attr, index, package) and \
                    not (isinstance(func.value, ast.Name) and
                         rebound_around(call, func.value.id, index)):
                owner = ast.unparse(func.value)
                yield Hit(Span(module.path, call.lineno, call.col_offset + 1),
                          f"`{ast.unparse(call)}` calls `{func.attr}` on the class `{owner}`, "
                          f"not on a node: Python raises TypeError (no `self`)",
                          f"Call it on the node: `node.{func.attr}()` (or `self.{func.attr}()` "
                          "in its methods)")


def _is_node_class(owner: ast.expr, method: str, index: Index, package: Package) -> bool:
    """True when ``owner`` is rclpy's ``Node`` class, or a class of the package deriving from
    it alone whose body does not bind ``method``."""
    if isinstance(owner, (ast.Name, ast.Attribute)) and index.qualified(owner) == _NODE:
        return True
    dotted = package_class(owner.id, index, package) if isinstance(owner, ast.Name) else None
    if dotted is None:
        return False
    cls, own_index = package_classes(package)[dotted]
    return derives_from_node_alone(cls, own_index) and method not in scope_bindings(cls)
