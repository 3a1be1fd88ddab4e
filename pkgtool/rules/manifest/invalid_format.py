"""MAN010: ``<package format>`` is not 1, 2 or 3."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.manifest.common import package_root
from pkgtool.rules.manifest.schema import FORMATS
from pkgtool.rules.registry import rule


@rule("MAN010", "invalid-format", Severity.ERROR,
      fix='Write `<package format="3">`')
def invalid_format(package: Package) -> Iterator[Hit]:
    """The ``format`` attribute of ``<package>`` is not exactly ``1``, ``2`` or ``3``.

    ## What it does
    Reports a ``format`` that is not one of the three package.xml formats (REP 127, 140, 149),
    or that has spaces or leading zeros. A missing ``format`` means format 1, which is valid;
    MAN006 reports format 2 and 3 tags in such a manifest. pkgtool checks nothing else in a
    manifest of an unknown format.

    ## Why is this bad?
    No schema accepts the manifest, and catkin_pkg stops with an assertion on a format it does
    not know, so colcon does not see a ROS package.

    ## Example
    ```xml
    <package format="3.0">
    ```

    ## Use instead
    ```xml
    <package format="3">
    ```
    """
    root = package_root(package)
    value = root.attribute("format") if root is not None else None
    if root is None or value is None or value in {str(f) for f in FORMATS}:
        return
    stripped = value.strip().lstrip("0")
    exact = stripped if stripped in {str(f) for f in FORMATS} else None
    yield Hit(root.span, f'`format="{value}"` is not a package.xml format (1, 2 or 3)',
              f'Write `format="{exact}"`' if exact else None)
