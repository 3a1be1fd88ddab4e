"""MAN004: a package.xml element stands where the schema's sequence does not allow it."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.manifest.common import misplaced, names_its_schema, tree
from pkgtool.rules.manifest.schema import ORDER_HINT
from pkgtool.rules.registry import rule


@rule("MAN004", "element-out-of-order", Severity.ERROR,
      fix="Move the element to where the schema's order puts it")
def element_out_of_order(package: Package) -> Iterator[Hit]:
    """The children of ``<package>`` are not in the order the package.xml schema requires.

    ## What it does
    Checks the order of the children of ``<package>`` against the XSD of the manifest's format:
    name, version, description, maintainer, license, url, author, then the dependency tags in
    any order among themselves, then (format 3) group_depend and member_of_group, then export.
    One finding per package.xml, at the first misplaced element; it lists the others. Only
    a manifest that names its schema (the `<?xml-model?>` line `ros2 pkg create` writes, or
    `xsi:noNamespaceSchemaLocation`) is checked: nothing validates the order of one that does
    not (`ament_xmllint` checks it is well-formed only, catkin_pkg and colcon read elements in
    any order).

    ## Why is this bad?
    The schemas define ``<package>`` as a sequence: a manifest in another order fails
    ``ament_xmllint`` (which newer ``ros2 pkg create`` templates run as a test), schema-aware
    editors and release checks.

    ## Example
    ```xml
    <license>MIT</license>
    <maintainer email="ada@example.com">Ada</maintainer>
    <exec_depend>rclpy</exec_depend>
    <url>https://example.com</url>
    ```

    ## Use instead
    ```xml
    <maintainer email="ada@example.com">Ada</maintainer>
    <license>MIT</license>
    <url>https://example.com</url>
    <exec_depend>rclpy</exec_depend>
    ```
    """
    found = tree(package)
    if found is None or not names_its_schema(package):
        return
    items = [item for item in misplaced(found) if not item.duplicate]
    if not items:
        return
    first, others = items[0], items[1:]
    message = (f"`<{first.element.tag}>` must come before `<{first.before.tag}>` "
               f"(line {first.before.span.line})")
    if others:
        message += "; also out of order: " + ", ".join(
            f"`<{o.element.tag}>` (line {o.element.span.line})" for o in others)
    moved = ", ".join(dict.fromkeys(f"`<{item.element.tag}>`" for item in items))
    yield Hit(first.element.span, message,
              f"Move {moved} up; the order is {ORDER_HINT[found.format]}",
              related=tuple(o.element.span for o in others))
