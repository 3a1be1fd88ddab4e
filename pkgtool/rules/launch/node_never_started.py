"""LCH007: a launch node assigned to a name the launch function never uses."""

from __future__ import annotations

import re
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.registry import rule


def _disabled(lines: list[str], line: int) -> bool:
    """True when a comment of the file uses the name assigned on ``line`` (1-based) as code
    does: the node was left out on purpose (``# talker,`` in the description's list,
    ``# ld.add_action(talker)``); not a comment that only tells of it in words."""
    assigned = re.match(r"\s*(\w+)\s*=", lines[line - 1]) if 0 < line <= len(lines) else None
    if assigned is None:
        return False
    name = re.escape(assigned.group(1))
    used = re.compile(rf"#\s*{name}\s*(?:[,#]|$)|#.*[\[(,]\s*{name}\s*[,)\]]")
    return any(used.search(text) for text in lines)


@rule("LCH007", "launch-node-never-started", Severity.WARNING,
      fix="Add the node to the returned `LaunchDescription([...])`, or delete it")
def launch_node_never_started(package: Package) -> Iterator[Hit]:
    """A Python launch file builds a node action that it never adds to the description.

    ## What it does
    Reports `Node(...)` (and the other node actions) whose call is the whole value of an
    assignment to a local name that its function never reads: no load of the name anywhere
    in the function, nested functions included, no `del`, `global`, `nonlocal`, `locals()`,
    `vars()`, `eval` or `exec`; a read as an event handler's `target_action=` does not count
    (the handler watches the action, it does not start it, and never fires).
    A node whose name a comment of the file uses as code would (`# rviz,` left in the list,
    `# ld.add_action(rviz)`) was disabled on purpose and is not reported; a comment that
    only tells of the node in words does not count.

    ## Why is this bad?
    Creating the action starts nothing: only actions in the returned `LaunchDescription`
    (or added to it) run. `ros2 launch` silently starts the other nodes, and the missing
    one is noticed much later. ament_flake8 also fails the package's tests on the unused
    name (F841).

    ## Example
    ```python
    talker = Node(package='demo', executable='talker')
    listener = Node(package='demo', executable='listener')
    return LaunchDescription([listener])
    ```

    ## Use instead
    ```python
    talker = Node(package='demo', executable='talker')
    listener = Node(package='demo', executable='listener')
    return LaunchDescription([talker, listener])
    ```
    """
    for launch in package.launch_files:
        lines = package.texts.get(launch.path, "").splitlines()
        for node in launch.nodes:
            if node.unused and not _disabled(lines, node.span.line):
                started = f"`{node.executable}`" if node.executable else "this node"
                action = f"`{node.action}` action" if node.action else \
                    "`ExecuteProcess` running `ros2 run`"
                yield Hit(node.span, f"The {action} for {started} is assigned to a name that "
                          "nothing uses to start it: the node is never started")
