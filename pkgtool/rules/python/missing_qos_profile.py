"""PYC007: a publisher or subscription created without a QoS profile."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import PARAMETERS, argument, qos_calls
from pkgtool.rules.registry import rule


_HINTS = {
    "queue_size": " (`queue_size` is ROS 1: pass the depth as `qos_profile`)",
    "qos": " (the keyword is `qos_profile`, not `qos`)",
    "depth": " (pass the depth as `qos_profile`)",
}


@rule("PYC007", "missing-qos-profile", Severity.ERROR,
      fix="Pass a QoS profile or a history depth as the last argument, e.g. `10`")
def missing_qos_profile(package: Package) -> Iterator[Hit]:
    """A publisher or subscription is created without a QoS profile.

    ## What it does
    Reports `create_publisher(msg_type, topic)` and
    `create_subscription(msg_type, topic, callback)` calls (and `create_lifecycle_publisher`)
    in installed modules that import rclpy, when every other required argument is given but
    `qos_profile` is not. Calls with `*args` or `**kwargs`, and modules defining a method of
    the same name, are not checked. The line reported is the one of the last argument, after
    which the profile belongs.

    ## Why is this bad?
    Since ROS 2 Foxy the QoS profile is a required argument: the node dies at start-up with
    `TypeError: create_subscription() missing 1 required positional argument:
    'qos_profile'`. Older tutorials and ROS 1 habits (`queue_size`) leave it out.

    ## Example
    ```python
    self.create_subscription(String, 'chatter', self.on_message)
    ```

    ## Use instead
    ```python
    self.create_subscription(String, 'chatter', self.on_message, 10)
    ```
    """
    for module, call, method in qos_calls(package):
        parameters = PARAMETERS[method]
        others = [p for p in parameters if p != "qos_profile"]
        if argument(call, parameters, "qos_profile") is None and len(call.args) <= len(others) \
                and all(argument(call, parameters, p) is not None for p in others):
            hint = next((_HINTS[k.arg] for k in call.keywords if k.arg in _HINTS), "")
            last = max([*call.args, *(k.value for k in call.keywords)],
                       key=lambda n: (n.end_lineno or 0, n.end_col_offset or 0))
            yield Hit(Span(module.path, last.end_lineno or call.lineno, call.col_offset + 1),
                      f"`{method}()` has no QoS profile{hint}")
