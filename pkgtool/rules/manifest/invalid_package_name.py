"""MAN001: the ``<name>`` is not a valid REP 144 package name."""

from __future__ import annotations

import re
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.manifest.common import tree
from pkgtool.rules.manifest.schema import NAME, token
from pkgtool.rules.registry import rule


def _reason(name: str) -> str:
    bad = sorted({c for c in name if not re.match(r"[a-z0-9_]", c)})
    if any(c.isupper() for c in bad):
        return "has uppercase letters"
    if bad:
        return "contains " + ", ".join(f"`{c}`" for c in bad)
    if not name[0].isalpha():
        return "does not start with a letter"
    return "has a double underscore" if "__" in name else "ends with an underscore"


def _suggestion(name: str) -> str | None:
    fixed = re.sub(r"_+", "_", re.sub(r"[^a-z0-9_]", "_", name.lower())).strip("_")
    return fixed if NAME.fullmatch(fixed) else None


@rule("MAN001", "invalid-package-name", Severity.ERROR,
      fix="Use lowercase letters, digits and single underscores, starting with a letter")
def invalid_package_name(package: Package) -> Iterator[Hit]:
    """The package name does not follow REP 144.

    ## What it does
    Checks every ``<name>`` against the schema's pattern: a lowercase letter, then lowercase
    letters, digits and single underscores, not ending with an underscore.

    ## Why is this bad?
    The package.xml schema rejects it, ``ros2 pkg create`` refuses it and bloom cannot release
    it; a dash cannot be a Python module's name. colcon and catkin_pkg only warn, so such a
    package may build and run in a workspace, but no other package can depend on it through
    a release.

    ## Example
    ```xml
    <name>My-Robot__Pkg</name>
    ```

    ## Use instead
    ```xml
    <name>my_robot_pkg</name>
    ```
    """
    found = tree(package)
    if found is None:
        return
    for element in found.named("name"):
        name = token(element.text)
        if element.children or NAME.fullmatch(name):
            continue
        if not name:
            yield Hit(element.span, "Package name is empty")
            continue
        suggestion = _suggestion(name)
        yield Hit(element.span, f"Package name `{name}` {_reason(name)}",
                  f"Rename the package to `{suggestion}`, also in setup.py and resource/"
                  if suggestion else None)
