"""PYC009: a Node constructed without a node name."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import name_argument, node_constructions, unpacks
from pkgtool.rules.syntax_trees import installed_trees
from pkgtool.rules.registry import rule


@rule("PYC009", "missing-node-name", Severity.ERROR,
      fix="Pass the node name: `super().__init__('my_node')`")
def missing_node_name(package: Package) -> Iterator[Hit]:
    """A `Node` is constructed without a node name.

    ## What it does
    Reports `super().__init__()` in classes derived from rclpy's `Node` (or `LifecycleNode`),
    and `Node()` or `rclpy.create_node()` calls, that pass no node name. Calls with `*args`
    or `**kwargs` are not checked.

    ## Why is this bad?
    `node_name` is a required argument of `Node.__init__`: the node dies at start-up with
    `TypeError: __init__() missing 1 required positional argument: 'node_name'`. ROS 1's
    `rospy.init_node()` took the name elsewhere, so ported code often leaves it out.

    ## Example
    ```python
    class Talker(Node):
        def __init__(self):
            super().__init__()
    ```

    ## Use instead
    ```python
    class Talker(Node):
        def __init__(self):
            super().__init__('talker')
    ```
    """
    for module, _, index in installed_trees(package):
        for call in node_constructions(index):
            if name_argument(call) is None and not unpacks(call):
                yield Hit(Span(module.path, call.lineno, call.col_offset + 1),
                          "The node is created without a name")
