"""MAN003: a required package.xml element is missing or empty."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.manifest.common import tree
from pkgtool.rules.manifest.schema import SEQUENCES
from pkgtool.rules.registry import rule

_EXAMPLES = {
    "name": "<name>my_pkg</name>",
    "version": "<version>0.1.0</version>",
    "description": "<description>What the package does</description>",
    "maintainer": '<maintainer email="you@example.com">Your Name</maintainer>',
    "license": "<license>Apache-2.0</license>",
}
_MUST_HAVE_TEXT = ("description", "license")
"""Elements catkin_pkg rejects when empty (the XSD alone would accept them)."""


@rule("MAN003", "missing-required-element", Severity.ERROR,
      fix="Add the missing element")
def missing_required_element(package: Package) -> Iterator[Hit]:
    """package.xml lacks ``name``, ``version``, ``description``, ``maintainer`` or ``license``.

    ## What it does
    Reports each element every package.xml format requires that is absent, and a
    ``<description>`` or ``<license>`` that is empty.

    ## Why is this bad?
    The schema requires these elements; catkin_pkg rejects a manifest without them, or with an
    empty description or license, so colcon does not see a ROS package at all.

    ## Example
    ```xml
    <package format="3">
      <name>my_pkg</name>
      <version>0.1.0</version>
      <description>Drives the robot</description>
    </package>
    ```

    ## Use instead
    ```xml
    <package format="3">
      <name>my_pkg</name>
      <version>0.1.0</version>
      <description>Drives the robot</description>
      <maintainer email="ada@example.com">Ada</maintainer>
      <license>Apache-2.0</license>
    </package>
    ```
    """
    found = tree(package)
    if found is None:
        return
    present = {child.tag for child in found.elements()}
    for slot in SEQUENCES[found.format]:
        tag = slot.tags[0]
        if slot.required and tag not in present:
            yield Hit(found.root.span, f"Required element `<{tag}>` is missing",
                      f"Add `{_EXAMPLES[tag]}`")
    for element in found.named(*_MUST_HAVE_TEXT):
        if not element.text and not element.children:
            yield Hit(element.span, f"`<{element.tag}>` is empty",
                      f"Fill in `{_EXAMPLES[element.tag]}`")
