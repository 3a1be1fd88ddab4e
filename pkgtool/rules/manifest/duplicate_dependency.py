"""MAN013: the same dependency tag on the same key twice."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.xml import XmlElement
from pkgtool.rules.manifest.common import dependency_key, snippet, tree
from pkgtool.rules.manifest.schema import DEPENDS_1, DEPENDS_2, GROUP_TAGS
from pkgtool.rules.registry import rule

_TAGS = frozenset(DEPENDS_1 + DEPENDS_2 + GROUP_TAGS) - {"depend"}
"""Repeated ``<depend>`` tags are MAN012: catkin_pkg rejects those."""


@rule("MAN013", "duplicate-dependency", Severity.WARNING,
      fix="Remove the repeated tag")
def duplicate_dependency(package: Package) -> Iterator[Hit]:
    """A dependency tag is repeated with the same key and attributes.

    ## What it does
    Reports the second and later occurrences of, for example, ``<exec_depend>numpy</exec_depend>``
    when the same tag already names the same key with the same version and condition attributes.
    (A repeated ``<depend>`` is MAN012.)

    ## Why is this bad?
    It changes nothing but makes the manifest harder to maintain: removing one copy later does
    not remove the dependency, and reviewers cannot tell which copy was meant.

    ## Example
    ```xml
    <exec_depend>numpy</exec_depend>
    <exec_depend>numpy</exec_depend>
    ```

    ## Use instead
    ```xml
    <exec_depend>numpy</exec_depend>
    ```
    """
    found = tree(package)
    if found is None:
        return
    first: dict[tuple[str, object], XmlElement] = {}
    for element in found.elements():
        if element.tag not in _TAGS:
            continue
        key = (element.tag, dependency_key(element))
        if key in first:
            yield Hit(element.span, f"`{snippet(element)}` repeats line {first[key].span.line}")
        else:
            first[key] = element
