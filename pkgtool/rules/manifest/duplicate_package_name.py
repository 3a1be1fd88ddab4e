"""MAN026: another package of the same colcon workspace has this package's name."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.manifest.common import tree
from pkgtool.rules.registry import rule


@rule("MAN026", "duplicate-package-name", Severity.ERROR,
      fix="Give each package its own name (in package.xml, setup.py, setup.cfg and "
          "resource/), or keep the copies out of the workspace with a `COLCON_IGNORE` file")
def duplicate_package_name(package: Package) -> Iterator[Hit]:
    """Another package of the same colcon workspace has the same name.

    ## What it does
    Compares the package's `<name>` with the names of the other packages under the same
    colcon `src` folder, and those of packages beside that `src` folder in no `src` folder
    themselves (`ws/driver/` and `ws/src/driver/`: colcon run in `ws` walks both). Folders
    colcon skips (a `COLCON_IGNORE` marker) are not part of the workspace; packages in no
    `src` folder are not compared otherwise (the chapters or lab sessions of one repository
    are often built one at a time).

    ## Why is this bad?
    `colcon build` stops before building anything: "Duplicate package names not supported".
    Copies of a package kept for each lab session or solution (`my_pkg/`, `my_pkg_solution/`)
    are the usual cause.

    ## Example
    ```text
    src/turtle_control/package.xml           <name>turtle_control</name>
    src/old/turtle_control_v1/package.xml    <name>turtle_control</name>
    ```

    ## Use instead
    ```text
    src/turtle_control/package.xml           <name>turtle_control</name>
    src/old/COLCON_IGNORE
    src/old/turtle_control_v1/package.xml    <name>turtle_control</name>
    ```
    """
    twins = package.context.twins
    found = tree(package) if twins else None
    element = next(found.named("name"), None) if found is not None else None
    if element is None:
        return
    others = ", ".join(f"`{twin}`" for twin in twins)
    yield Hit(element.span, f"`{package.name}` is also the name of the package"
              f"{'s' * (len(twins) > 1)} in {others}: "
              "colcon refuses to build a workspace with two packages of one name")
