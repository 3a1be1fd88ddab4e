"""MAN011: a single-valued package.xml element appears more than once."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.manifest.common import misplaced, tree
from pkgtool.rules.registry import rule


@rule("MAN011", "duplicate-element", Severity.ERROR,
      fix="Keep one of the elements and merge the other into it")
def duplicate_element(package: Package) -> Iterator[Hit]:
    """``<name>``, ``<version>``, ``<description>`` or ``<export>`` appears more than once.

    ## What it does
    Reports every repeated occurrence of an element the schema allows only once.

    ## Why is this bad?
    The schema rejects it and catkin_pkg refuses the manifest ("must contain exactly one"),
    so colcon does not see a ROS package. A second ``<export>`` is a frequent way to lose the
    ``<build_type>``.

    ## Example
    ```xml
    <export><build_type>ament_python</build_type></export>
    <export><rosdoc config="rosdoc.yaml"/></export>
    ```

    ## Use instead
    ```xml
    <export>
      <build_type>ament_python</build_type>
      <rosdoc config="rosdoc.yaml"/>
    </export>
    ```
    """
    found = tree(package)
    if found is None:
        return
    for item in misplaced(found):
        if item.duplicate:
            yield Hit(item.element.span,
                      f"`<{item.element.tag}>` appears again (first on line "
                      f"{item.before.span.line}); only one is allowed",
                      "Merge the two into one element" if item.element.tag == "export"
                      else "Remove the extra element")
