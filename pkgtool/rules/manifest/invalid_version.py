"""MAN002: the ``<version>`` is not ``X.Y.Z``."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.manifest.common import tree
from pkgtool.rules.manifest.schema import VERSION, token
from pkgtool.rules.registry import rule
from pkgtool.lazy_regex import lazy_pattern

_NUMBERS = lazy_pattern(r"v?([0-9]+)(?:\.([0-9]+))?(?:\.([0-9]+))?")
_CATKIN_VERSION = lazy_pattern(r"[0-9]+\.[0-9]+\.[0-9]+")


def _suggestion(version: str) -> str | None:
    match = _NUMBERS.fullmatch(version)
    if not match:
        return None
    return ".".join(str(int(part or 0)) for part in match.groups())


def _message(version: str) -> str:
    if not version:
        return "Package version is empty"
    if _CATKIN_VERSION.fullmatch(version):
        return f"Package version `{version}` has a leading zero"
    return f"Package version `{version}` is not three numbers `X.Y.Z`"


@rule("MAN002", "invalid-version", Severity.ERROR,
      fix="Write the version as three dot-separated numbers without leading zeros")
def invalid_version(package: Package) -> Iterator[Hit]:
    """The package version is not ``X.Y.Z`` with non-negative integers and no leading zeros.

    ## What it does
    Checks ``<version>`` against the schema's pattern, and the format 3 ``compatibility``
    attribute against what catkin_pkg accepts (``X.Y.Z``).

    ## Why is this bad?
    The schema rejects other versions; catkin_pkg (and so colcon and bloom) refuses versions
    that are not three numbers, and release tooling compares versions numerically.

    ## Example
    ```xml
    <version>1.0</version>
    ```

    ## Use instead
    ```xml
    <version>1.0.0</version>
    ```
    """
    found = tree(package)
    if found is None:
        return
    for element in found.named("version"):
        version = token(element.text)
        if not element.children and not VERSION.fullmatch(version):
            suggestion = _suggestion(version)
            yield Hit(element.span, _message(version),
                      f"Write `{suggestion}`" if suggestion and suggestion != version else None)
        compatibility = element.attribute("compatibility")
        if found.format != 3 or compatibility is None:
            continue
        if not _CATKIN_VERSION.fullmatch(token(compatibility)):
            yield Hit(element.span, f"Compatibility version `{compatibility}` is not `X.Y.Z`")
