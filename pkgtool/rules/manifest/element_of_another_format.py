"""MAN006: a package.xml tag that only another format defines."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.xml import XmlElement
from pkgtool.rules.manifest.common import Tree, tree
from pkgtool.rules.manifest.schema import ALL_TAGS, formats_with, tags_of
from pkgtool.rules.registry import rule


def _hit(found: Tree, element: XmlElement) -> Hit:
    tag = element.tag
    if tag == "run_depend":
        return Hit(element.span, f"`<run_depend>` is a format 1 tag, not format {found.format}",
                   "Replace it with `<exec_depend>` (plus `<build_export_depend>` if other "
                   "packages build against it)")
    needs = " or ".join(str(f) for f in formats_with(tag))
    if found.root.attribute("format") is None:
        return Hit(element.span, f"`<{tag}>` needs format {needs}, but `<package>` has no "
                   "`format` attribute, which means format 1",
                   'Add `format="3"` to `<package>`')
    return Hit(element.span, f"`<{tag}>` needs format {needs}, not format {found.format}",
               'Set `format="3"` on `<package>`')


@rule("MAN006", "element-of-another-format", Severity.ERROR,
      fix='Use the tags of the declared format, or declare `format="3"`')
def element_of_another_format(package: Package) -> Iterator[Hit]:
    """A child of ``<package>`` belongs to another package.xml format than the declared one.

    ## What it does
    Reports ``<run_depend>`` in formats 2 and 3; ``<depend>``, ``<exec_depend>``,
    ``<build_export_depend>``, ``<buildtool_export_depend>`` and ``<doc_depend>`` in format 1
    (which is what a ``<package>`` without ``format`` attribute is); and ``<group_depend>`` or
    ``<member_of_group>`` before format 3.

    ## Why is this bad?
    The schema rejects these tags and catkin_pkg refuses the manifest ("must not contain the
    following tags"), so colcon does not see a ROS package and rosdep ignores it.

    ## Example
    ```xml
    <package format="2">
      ...
      <run_depend>rclpy</run_depend>
    </package>
    ```

    ## Use instead
    ```xml
    <package format="3">
      ...
      <exec_depend>rclpy</exec_depend>
    </package>
    ```
    """
    found = tree(package)
    if found is None:
        return
    known = tags_of(found.format)
    for element in found.root.children:
        if element.tag in ALL_TAGS and element.tag not in known:
            yield _hit(found, element)
