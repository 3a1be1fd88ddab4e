"""DAT003: the ament index marker is missing or not installed."""

from __future__ import annotations

import posixpath
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.installed import keyword_known
from pkgtool.model.package import Package
from pkgtool.rules.data_files.common import entries_to, source_names
from pkgtool.rules.plain_projects import MARKER_FOLDER
from pkgtool.rules.registry import rule
from pkgtool.rules.setup_values import checked_setup, name_cause


_UNFOUND = ("only colcon's fallback (deprecated) installs the right one; released or "
            "pip-installed, ROS 2 cannot find the package")


@rule("DAT003", "unregistered-package", Severity.ERROR,
      fix="Create the empty file `resource/<package>` and add `('share/ament_index/"
          "resource_index/packages', ['resource/' + package_name])` to data_files")
def unregistered_package(package: Package) -> Iterator[Hit]:
    """The package does not install its ament index marker.

    ## What it does
    Checks that data_files installs a file named like the package (package.xml's name) into
    `share/ament_index/resource_index/packages`. A declared marker whose file is missing is
    reported by DAT001 instead.

    ## Why is this bad?
    ROS 2 finds installed packages through this marker only. colcon still adds a missing one
    itself, with a warning that this fallback will be removed; a release build (bloom's
    Debian packages) or a pip install does not, and there `ros2 run`, `ros2 launch`,
    `ros2 pkg list` and `get_package_share_directory()` report "package not found", although
    the build succeeded.

    ## Example
    ```python
    data_files=[('share/' + package_name, ['package.xml'])]
    ```

    ## Use instead
    ```python
    data_files=[('share/ament_index/resource_index/packages', ['resource/' + package_name]),
                ('share/' + package_name, ['package.xml'])]
    ```
    """
    setup = checked_setup(package)
    if setup is None or setup.setup_span is None or not keyword_known(package, "data_files"):
        return
    declared = list(entries_to(package, MARKER_FOLDER))
    names = {posixpath.basename(n) for _, source in declared for n in source_names(source)}
    if package.name in names:
        return
    if declared:
        entry = declared[0][0]
        shown = ", ".join(f"`{n}`" for n in sorted(names)) or "nothing"
        yield Hit(entry.span, f"The ament index marker installed is {shown}, not "
                              f"`{package.name}`: {_UNFOUND}",
                  cause=name_cause(min(names)) if len(names) == 1 else "",
                  consequence=True)
        return
    elsewhere = next((e for e in setup.data_files or () for source in e.sources
                      for n in source_names(source) if posixpath.basename(n) == package.name
                      and ("ament_index" in e.destination or n.startswith("resource/"))), None)
    if elsewhere is not None:
        yield Hit(elsewhere.span, f"The ament index marker `{package.name}` is installed to "
                                  f"`{elsewhere.destination}`, not `{MARKER_FOLDER}`: "
                                  f"{_UNFOUND}",
                  f"Install it to `'{MARKER_FOLDER}'`")
    else:
        yield Hit(setup.setup_span, f"Nothing installs `{MARKER_FOLDER}/{package.name}`: "
                                    f"{_UNFOUND}")
