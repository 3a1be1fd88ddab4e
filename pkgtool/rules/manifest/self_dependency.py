"""MAN014: the package depends on itself, or on a group it is a member of."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.manifest.common import snippet, tree
from pkgtool.rules.manifest.schema import token
from pkgtool.rules.registry import rule


@rule("MAN014", "self-dependency", Severity.ERROR,
      fix="Remove the dependency on the package itself")
def self_dependency(package: Package) -> Iterator[Hit]:
    """A ``*_depend`` names the package itself, or a ``<group_depend>`` a group it belongs to.

    ## What it does
    Reports every dependency tag whose key is the package's own ``<name>``, and every
    ``<group_depend>`` on a group that a ``<member_of_group>`` of the same manifest joins.

    ## Why is this bad?
    catkin_pkg rejects the manifest ("must not depend on a package with the same name"), so
    colcon does not see a ROS package; a package cannot be built before itself. It usually
    comes from ``ros2 pkg create --dependencies`` listing the new package's own name.

    ## Example
    ```xml
    <name>my_pkg</name>
    ...
    <exec_depend>my_pkg</exec_depend>
    ```

    ## Use instead
    ```xml
    <name>my_pkg</name>
    ...
    <exec_depend>rclpy</exec_depend>
    ```
    """
    found = tree(package)
    if found is None:
        return
    name = (found.manifest.name.value if found.manifest.name else "") or None
    groups = {token(m.text): m for m in found.named("member_of_group")}
    for element in found.elements():
        key = token(element.text)
        if element.tag == "group_depend" and key in groups:
            yield Hit(element.span, f"`{snippet(element)}` names a group this package is a "
                      f"member of (line {groups[key].span.line})",
                      "Remove the `<group_depend>` or the `<member_of_group>`")
        elif element.tag.endswith("depend") and element.tag != "group_depend" and key == name:
            yield Hit(element.span, f"`{snippet(element)}` is a dependency on the package itself")
