"""DAT004: package.xml is not installed to share/<package>."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.installed import keyword_known
from pkgtool.model.package import Package
from pkgtool.rules.data_files.common import entries_to, source_names
from pkgtool.rules.registry import rule
from pkgtool.rules.setup_values import checked_setup, name_cause


@rule("DAT004", "uninstalled-package-xml", Severity.WARNING,
      fix="Add `('share/' + package_name, ['package.xml'])` to data_files")
def uninstalled_package_xml(package: Package) -> Iterator[Hit]:
    """data_files does not install package.xml into `share/<package>`.

    ## What it does
    Checks that data_files installs the package's own `package.xml` into
    `share/<name>` (package.xml's name).

    ## Why is this bad?
    Tools that inspect installed packages read `share/<package>/package.xml`: `ros2 pkg xml`,
    dependency resolution of packages built on top of this one, and colcon's package discovery
    in underlay workspaces.

    ## Example
    ```python
    data_files=[('share/ament_index/resource_index/packages', ['resource/' + package_name])]
    ```

    ## Use instead
    ```python
    data_files=[
        ('share/' + package_name, ['package.xml']),
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
    ]
    ```
    """
    setup = checked_setup(package)
    if setup is None or setup.setup_span is None or not keyword_known(package, "data_files"):
        return
    share = f"share/{package.name}"
    if any("package.xml" in source_names(s) for _, s in entries_to(package, share)):
        return
    elsewhere = next((e for e in setup.data_files or () for source in e.sources
                      if "package.xml" in source_names(source)), None)
    if elsewhere is not None:
        yield Hit(elsewhere.span, f"`package.xml` is installed to `{elsewhere.destination}`, "
                                  f"not `{share}`", "Install it to `'share/' + package_name`",
                  cause=name_cause(elsewhere.destination.strip("/").removeprefix("share/")),
                  consequence=True)
    else:
        yield Hit(setup.setup_span, f"`package.xml` is not installed to `{share}`")
