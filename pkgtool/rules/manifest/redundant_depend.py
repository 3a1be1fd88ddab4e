"""MAN012: a dependency that a ``<depend>`` (or, in format 1, a build/run dependency) repeats."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.xml import XmlElement
from pkgtool.rules.manifest.common import dependency_key, snippet, tree
from pkgtool.rules.registry import rule

_COVERED = {2: ("depend", ("build_depend", "build_export_depend", "exec_depend", "depend")),
            3: ("depend", ("build_depend", "build_export_depend", "exec_depend", "depend")),
            1: ("test_depend", ("build_depend", "run_depend"))}
"""Per format: the tag catkin_pkg checks, and the tags it must not repeat."""


def _redundant(elements: list[XmlElement], fmt: int) -> Iterator[tuple[XmlElement, XmlElement]]:
    """(the element to remove, the element it repeats), as catkin_pkg's checks pair them."""
    checked, others = _COVERED[fmt]
    for index, element in enumerate(elements):
        if element.tag != checked:
            continue
        for position, other in enumerate(elements):
            if other.tag not in others or dependency_key(other) != dependency_key(element):
                continue
            if other.tag != element.tag:
                yield (element, other) if fmt == 1 else (other, element)
            elif position < index:
                yield element, other


@rule("MAN012", "redundant-depend", Severity.ERROR,
      fix="Remove the redundant tag")
def redundant_depend(package: Package) -> Iterator[Hit]:
    """A ``<depend>`` is repeated by a ``build_depend``, ``build_export_depend``, ``exec_depend``.

    ## What it does
    In formats 2 and 3, reports a ``<build_depend>``, ``<build_export_depend>``,
    ``<exec_depend>`` or second ``<depend>`` on the same key, with the same version and
    condition attributes, as a ``<depend>``: ``<depend>`` already means all three. In format 1,
    reports a ``<test_depend>`` that repeats a ``<build_depend>`` or ``<run_depend>``.

    ## Why is this bad?
    catkin_pkg rejects the manifest ("The generic dependency on ... is redundant"), so colcon
    does not see a ROS package and builds it, if at all, as a plain Python package.

    ## Example
    ```xml
    <depend>rclpy</depend>
    <exec_depend>rclpy</exec_depend>
    ```

    ## Use instead
    ```xml
    <depend>rclpy</depend>
    ```
    """
    found = tree(package)
    if found is None:
        return
    reported: set[int] = set()
    for element, other in _redundant(list(found.elements()), found.format):
        if id(element) in reported:
            continue
        reported.add(id(element))
        yield Hit(element.span, f"`{snippet(element)}` is redundant with `{snippet(other)}` "
                  f"(line {other.span.line})",
                  f"Remove this `<{element.tag}>`: `<{other.tag}>` already covers it")
