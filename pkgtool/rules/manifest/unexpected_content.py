"""MAN005: package.xml holds an element or text that no package.xml format allows there."""

from __future__ import annotations

import difflib
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity, shortened
from pkgtool.model.package import Package
from pkgtool.rules.manifest.common import names_its_schema, tree
from pkgtool.rules.manifest.schema import ALL_TAGS, TEXT_ONLY, tags_of
from pkgtool.rules.registry import rule


@rule("MAN005", "unexpected-content", Severity.ERROR,
      fix="Remove it, or move it into `<export>` if a tool reads it from there")
def unexpected_content(package: Package) -> Iterator[Hit]:
    """package.xml contains an unknown element, a nested element, or stray text.

    ## What it does
    Reports a root element other than ``<package>``; children of ``<package>`` that no format
    defines (with the likely intended tag); elements inside elements that hold only text, such
    as ``<maintainer>`` or ``<depend>``; and text between the elements of ``<package>`` when
    package.xml names its schema (an `<?xml-model?>` line or `xsi:noNamespaceSchemaLocation`:
    without one, `ament_xmllint` checks only that the XML is well-formed, and catkin_pkg
    ignores the text). Tags of another format are MAN006. ``<description>`` and ``<export>``
    may contain anything.

    ## Why is this bad?
    The schema rejects all of these (`ament_xmllint`, run by `colcon test` where
    `ament_lint_common` is a test dependency, fails), and catkin_pkg refuses unknown tags and
    nested elements, so colcon does not see a ROS package; stray text fails the schema check
    alone (often a comment written as `// ...` or `# ...`). A misspelt dependency tag is
    silently not a dependency for any tool that does not validate.

    ## Example
    ```xml
    <exec_depends>rclpy</exec_depends>
    <maintainer email="ada@example.com">Ada <b>Lovelace</b></maintainer>
    <license>MIT</license>>
    ```

    ## Use instead
    ```xml
    <exec_depend>rclpy</exec_depend>
    <maintainer email="ada@example.com">Ada Lovelace</maintainer>
    <license>MIT</license>
    ```
    """
    manifest = package.manifest
    if manifest is not None and manifest.root.tag != "package":
        yield Hit(manifest.root.span, f"Root element is `<{manifest.root.tag}>`, not `<package>`",
                  "Make `<package format=\"3\">` the root element")
        return
    found = tree(package)
    if found is None:
        return
    known = tags_of(found.format)
    for child in found.root.children:
        if child.tag == "build_type":
            yield Hit(child.span, "`<build_type>` stands directly in `<package>`",
                      "Move it into `<export>`")
        elif child.tag not in ALL_TAGS:
            close = difflib.get_close_matches(child.tag, sorted(known), n=1, cutoff=0.75)
            yield Hit(child.span, f"Unknown element `<{child.tag}>` in `<package>`",
                      f"Rename it to `<{close[0]}>`" if close else None)
        elif child.tag in TEXT_ONLY:
            for nested in child.children:
                yield Hit(nested.span,
                          f"`<{child.tag}>` may contain only text, not `<{nested.tag}>`",
                          f"Remove the `<{nested.tag}>` tags and keep their text")
    for line, text in found.root.loose_text if names_its_schema(package) else ():
        yield Hit(found.root.span.at(line, 1),
                  f"Text `{shortened(text)}` is not allowed between the elements of `<package>`",
                  "Remove the stray text, or put it in a comment")
