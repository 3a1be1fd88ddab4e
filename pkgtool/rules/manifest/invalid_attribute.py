"""MAN009: an attribute the package.xml schema does not allow, or a dependency attribute value."""

from __future__ import annotations

import difflib
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.xml import XmlElement
from pkgtool.rules.manifest.common import Tree, tree
from pkgtool.rules.manifest.schema import (DEPEND_CONDITION, GROUP_CONDITION, GROUP_TAGS,
                                           VERSION_ATTRIBUTES, VERSION_LIMIT, XSI,
                                           allowed_attributes, attribute_label, token)
from pkgtool.rules.registry import rule

_FORMAT_3_ONLY = frozenset({"condition", "file", "compatibility"})


def _unknown(found: Tree, element: XmlElement, key: str) -> Hit:
    name, tag = attribute_label(key), element.tag
    if key in _FORMAT_3_ONLY and key in allowed_attributes(tag, 3):
        return Hit(element.span, f"`{name}` on `<{tag}>` needs format 3, not format "
                   f"{found.format}", 'Set `format="3"` on `<package>`')
    allowed = sorted(allowed_attributes(tag, found.format))
    close = difflib.get_close_matches(name, allowed, n=1, cutoff=0.7)
    return Hit(element.span, f"`<{tag}>` has no attribute `{name}`",
               f"Rename it to `{close[0]}`" if close else f"Remove `{name}`")


def _bad_value(element: XmlElement, key: str, value: str) -> Hit | None:
    if key in VERSION_ATTRIBUTES and not VERSION_LIMIT.fullmatch(token(value)):
        return Hit(element.span, f"`{key}=\"{value}\"` is not a version (`X`, `X.Y` or `X.Y.Z`)",
                   "Write the version as dot-separated numbers without leading zeros")
    pattern = GROUP_CONDITION if element.tag in GROUP_TAGS else DEPEND_CONDITION
    if key == "condition" and not pattern.fullmatch(value):
        return Hit(element.span, f"Condition `{value}` has characters a condition cannot contain",
                   "Compare `$VARIABLE`s with words or numbers, e.g. "
                   "`condition=\"$ROS_VERSION == 2\"`")
    return None


def _elements(found: Tree) -> Iterator[XmlElement]:
    yield found.root
    yield from found.elements()


@rule("MAN009", "invalid-attribute", Severity.ERROR,
      fix="Remove the attribute or correct its value")
def invalid_attribute(package: Package) -> Iterator[Hit]:
    """An element of package.xml has an attribute its format does not define, or a bad value.

    ## What it does
    Checks the attributes of ``<package>`` and its children against the manifest's format:
    dependency tags take ``version_lt``, ``version_lte``, ``version_eq``, ``version_gte``,
    ``version_gt`` (``X``, ``X.Y`` or ``X.Y.Z``) and, in format 3 only, ``condition``;
    ``<license file>`` and ``<version compatibility>`` are format 3 only; other elements take
    none beyond those of MAN007, MAN008 and MAN010. ``xsi:`` attributes are always allowed.

    ## Why is this bad?
    The schema rejects the manifest and catkin_pkg refuses unknown attributes, so colcon does
    not see a ROS package. A misspelt ``version_gte`` or a ``condition`` in format 2 is
    otherwise silently ignored, and the dependency is not what it says.

    ## Example
    ```xml
    <package format="2">
      ...
      <exec_depend condition="$ROS_VERSION == 2" version_gte="1.0-2">rclpy</exec_depend>
    </package>
    ```

    ## Use instead
    ```xml
    <package format="3">
      ...
      <exec_depend condition="$ROS_VERSION == 2" version_gte="1.0">rclpy</exec_depend>
    </package>
    ```
    """
    found = tree(package)
    if found is None:
        return
    for element in _elements(found):
        allowed = allowed_attributes(element.tag, found.format)
        for key, value in element.attributes:
            if key.startswith(XSI):
                continue
            hit = _bad_value(element, key, value) if key in allowed else \
                _unknown(found, element, key)
            if hit:
                yield hit
