"""SET003: setup.py's name differs from package.xml's."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.registry import rule
from pkgtool.rules.setup_values import beside_manifest, name_cause, setup_alias


@rule("SET003", "setup-name-mismatch", Severity.WARNING,
      fix="Use the `package.xml` name in `setup(name=...)`, e.g. through `package_name`")
def setup_name_mismatch(package: Package) -> Iterator[Hit]:
    """`setup(name=...)` is not the name in package.xml.

    ## What it does
    Compares the statically known `name` keyword of `setup()` with package.xml's `<name>`.
    When the package's folder has setup.py's name, package.xml's `<name>` is the odd one
    out, and the finding is reported there.

    ## Why is this bad?
    ROS tools know the package by its package.xml name, setuptools by the setup.py name: the
    installed egg-info, the console script wrappers and the ament index marker (usually built
    from the same variable) drift apart, and `ros2 run` or `ros2 pkg` may not find the package.

    ## Example
    ```python
    setup(name='robot-monitor', ...)   # package.xml: <name>robot_monitor</name>
    ```

    ## Use instead
    ```python
    package_name = 'robot_monitor'
    setup(name=package_name, ...)
    ```
    """
    found = beside_manifest(package, "name")
    if found and setup_alias(package):
        name, span, wanted = found
        manifest = package.manifest
        if package.root.name == name and manifest is not None and manifest.name is not None:
            yield Hit(manifest.name.span, f"The `package.xml` name `{wanted}` differs from "
                      f"`{name}`, the name of setup.py and of the package's folder: ROS tools "
                      f"look for `{wanted}`, which setup.py does not install",
                      f"Write `<name>{name}</name>`, or rename setup.py's name and the folder "
                      f"to `{wanted}`", cause=name_cause(name))
            return
        yield Hit(span, f"`setup.py` name `{name}` differs from the `package.xml` name "
                        f"`{wanted}`", cause=name_cause(name))
