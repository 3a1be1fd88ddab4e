"""DAT024: data_files installs into the ament index's package list a marker of another name than
the package's."""

from __future__ import annotations

import posixpath
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.installed import installed_data, keyword_known
from pkgtool.model.package import Package
from pkgtool.rules.data_files.common import entries_to, source_names
from pkgtool.rules.plain_projects import MARKER_FOLDER
from pkgtool.rules.registry import rule
from pkgtool.rules.setup_values import checked_setup


@rule("DAT024", "foreign-index-marker", Severity.WARNING,
      fix="Install only `resource/<package>` into `share/ament_index/resource_index/packages`, "
          "and the other files into `share/<package>`")
def foreign_index_marker(package: Package) -> Iterator[Hit]:
    """data_files installs a file of another name beside the package's ament index marker.

    ## What it does
    Reports each file data_files installs into `share/ament_index/resource_index/packages`
    other than the marker named like the package, when that marker is installed too (DAT003
    reports a package installing none), and data_files installs no share folder of that name
    (a second name the package is registered under on purpose has one).

    ## Why is this bad?
    Every file of that folder registers a package of its name: `ros2 pkg list` shows a
    package `visualize.rviz`, `ros2 pkg prefix` and `get_package_share_directory()` find it,
    and its share folder does not exist. Two packages installing the same stray file also
    collide when installed into one prefix (a Debian file conflict). The file itself is not
    where its users look for it (`share/<package>/`).

    ## Example
    ```python
    ('share/ament_index/resource_index/packages',
     ['resource/' + package_name, 'resource/visualize.rviz']),
    ```

    ## Use instead
    ```python
    ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
    ('share/' + package_name + '/rviz', ['resource/visualize.rviz']),
    ```
    """
    setup = checked_setup(package)
    if setup is None or not keyword_known(package, "data_files"):
        return
    declared = [(entry, name) for entry, source in entries_to(package, MARKER_FOLDER)
                for name in sorted(source_names(source))]
    if not any(posixpath.basename(name) == package.name for _, name in declared):
        return
    shared = {target.split("/")[1] for target in installed_data(package) or ()
              if target.startswith("share/") and target.count("/") > 1}
    for entry, name in declared:
        if posixpath.basename(name) not in (package.name, *shared):  # not an alias installed
            yield Hit(entry.span, f"`{name}` is installed into `{MARKER_FOLDER}`: ROS 2 now "
                                  f"knows a package `{posixpath.basename(name)}`, whose share "
                                  "folder does not exist")
