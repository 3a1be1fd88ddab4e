"""PYC030: rclpy's create_* methods given their arguments in another order (ROS 1's)."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import PARAMETERS, node_api_calls, swapped_argument, unpacks
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import installed_trees


@rule("PYC030", "swapped-rclpy-arguments", Severity.ERROR,
      fix="Pass the type first, then the name: `create_publisher(String, 'chatter', 10)`")
def swapped_rclpy_arguments(package: Package) -> Iterator[Hit]:
    """A publisher, subscription, service, client or timer is created with its arguments in
    the wrong order.

    ## What it does
    Reports `create_publisher`, `create_subscription`, `create_service` and `create_client`
    calls whose first positional argument is a string (`'chatter'`) or whose second is a
    message or service class imported from a `.msg`/`.srv` module (the topic and the type
    swapped, as ROS 1's `rospy.Publisher('chatter', String)` had them), `create_subscription`
    and `create_service` calls whose second is a lambda or a method of the class (the
    callback where the name goes), and `create_timer` calls whose first argument is one (the
    callback where the period goes) or whose third is a number (a QoS depth where the
    callback group goes: `'int' object has no attribute 'add_entity'`, checked on Jazzy).
    Only modules importing rclpy are looked at, not calls with `*args` or `**kwargs`, and not
    when the package defines a function of the same name.

    ## Why is this bad?
    rclpy checks the type: a string raises (`'str' object has no attribute
    '_TYPE_SUPPORT'`), and `create_timer` converts its first argument with `float()`,
    which raises `TypeError` for a method. The node dies at start-up.

    ## Example
    ```python
    self.publisher = self.create_publisher('chatter', String, 10)
    self.timer = self.create_timer(self.publish, 0.5)
    ```

    ## Use instead
    ```python
    self.publisher = self.create_publisher(String, 'chatter', 10)
    self.timer = self.create_timer(0.5, self.publish)
    ```
    """
    defined = {function.name for _, _, index in installed_trees(package)
               for function in index.functions}
    methods = {*PARAMETERS, "create_timer"} - defined
    for module, call, method, index in node_api_calls(package, methods):
        found = None if unpacks(call) else swapped_argument(call, method, index)
        if found:
            yield Hit(Span(module.path, found[0].lineno, found[0].col_offset + 1),
                      f"`{method}()` has its arguments out of order: {found[1]}; rclpy raises "
                      "at start-up")
