"""LCH022: a launch file starts two nodes under the same name in the same namespace."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.launch import NodeRef
from pkgtool.model.package import Package
from pkgtool.rules.registry import rule


def _full_name(node: NodeRef) -> str | None:
    """``/namespace/name`` of a node the launch file always starts, when both are static."""
    if not node.always_started or node.name_unknown or not node.name or node.unused or \
            node.optional or node.other_distros or node.composable or \
            (node.namespace is None and "namespace" in node.arguments):
        return None
    namespace = (node.namespace or "").strip("/")
    return f"/{namespace}/{node.name}" if namespace else f"/{node.name}"


@rule("LCH022", "duplicate-node-name", Severity.WARNING,
      fix="Give each node its own `name=`, or start them in different namespaces")
def duplicate_node_name(package: Package) -> Iterator[Hit]:
    """A launch file starts two nodes under the same name in the same namespace.

    ## What it does
    Reports a node action whose static `name=` and namespace repeat those of an earlier node
    of the same launch file, when the launch file starts both every time: both listed in
    the returned `LaunchDescription` (or added to it) by straight-line code of
    `generate_launch_description`, neither under a `condition=`, an `if`, a loop or a group,
    and neither renaming its namespace with a `__ns` remapping (XML: both directly under
    `<launch>`, with no `if` or `unless`).

    ## Why is this bad?
    ROS 2 starts both, but the graph then holds two nodes that share one name: `ros2 node
    list` warns, `ros2 param` and parameter services reach only one of them, and their log
    publishers and action servers collide. It is usually a copied `Node(...)` block whose
    name was not changed.

    ## Example
    ```python
    return LaunchDescription([
        Node(package='turtlesim', executable='turtlesim_node', name='sim'),
        Node(package='turtlesim', executable='turtlesim_node', name='sim'),
    ])
    ```

    ## Use instead
    ```python
    return LaunchDescription([
        Node(package='turtlesim', executable='turtlesim_node', name='sim1'),
        Node(package='turtlesim', executable='turtlesim_node', name='sim2'),
    ])
    ```
    """
    for launch in package.launch_files:
        seen: dict[str, NodeRef] = {}
        for node in launch.nodes:
            full = _full_name(node)
            if full is None:
                continue
            first = seen.setdefault(full, node)
            if first is not node:
                yield Hit(node.span, f"This node is named `{full}`, as is the node started on "
                          f"line {first.span.line}: two nodes of one name run side by side")
