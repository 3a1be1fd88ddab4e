"""PYC004: rclpy attributes that do not exist, such as ``ActionClient.GoalStatus``."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rclpy_missing import missing_attribute
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.syntax_trees import installed_trees, resolved_attributes
from pkgtool.rules.registry import rule


@rule("PYC004", "rclpy-missing-attribute", Severity.ERROR,
      fix="Use the rclpy API that exists (see the message)")
def rclpy_missing_attribute(package: Package) -> Iterator[Hit]:
    """Installed code uses an rclpy attribute that does not exist.

    ## What it does
    Reports reads of attributes that rclpy does not have, from a curated table checked
    against rclpy itself: `ActionClient.GoalStatus` (GoalStatus is a message in
    `action_msgs.msg`), rospy habits such as `rclpy.is_shutdown()`, `rclpy.loginfo()`,
    `rclpy.Node` (also as a module: `from rclpy.Node import Node`) or `Time.now()`. Only names
    bound solely to rclpy imports are checked, and not in annotations Python never evaluates
    (`self.node: rclpy.Node = node` in a method, any under `from __future__ import
    annotations`): a type checker's business.

    ## Why is this bad?
    The line raises `AttributeError` when it runs, often inside a callback, where the
    error shows up as a log line and the node silently stops doing its job.

    ## Example
    ```python
    if status == ActionClient.GoalStatus.STATUS_SUCCEEDED:
    ```

    ## Use instead
    ```python
    from action_msgs.msg import GoalStatus
    if status == GoalStatus.STATUS_SUCCEEDED:
    ```
    """
    for module, _, index in installed_trees(package):
        for node, owner, attr in resolved_attributes(index):
            use = missing_attribute(owner, attr) if owner.split(".")[0] == "rclpy" else None
            if use and not index.in_unevaluated_annotation(node):
                shown = f"{owner.rsplit('.', 1)[-1]}.{attr}"
                where = "" if owner == "rclpy" else " in rclpy"
                yield Hit(Span(module.path, node.lineno, node.col_offset + 1),
                          f"`{shown}` does not exist{where}", f"Use {use}")
        for node in index.import_froms:
            owner, _, leaf = (node.module or "").rpartition(".")
            use = missing_attribute(owner, leaf) if node.level == 0 and owner == "rclpy" else None
            if use:  # `from rclpy.Node import Node`: no such module
                yield Hit(Span(module.path, node.lineno, node.col_offset + 1),
                          f"`{node.module}` does not exist in rclpy", f"Use {use}")
            elif node.level == 0 and node.module:
                for alias in node.names:
                    use = missing_attribute(node.module, alias.name)
                    if use and node.module.split(".")[0] == "rclpy":
                        yield Hit(Span(module.path, node.lineno, node.col_offset + 1),
                                  f"`{node.module}` has no `{alias.name}`", f"Use {use}")
