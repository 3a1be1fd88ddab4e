"""DAT022: data_files installs a folder's files into a share folder of a misspelt name."""

from __future__ import annotations

import posixpath
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rosdistro import digits_differ, is_typo
from pkgtool.model.package import Package
from pkgtool.rules.data_files.common import destination_parts
from pkgtool.rules.registry import rule
from pkgtool.rules.setup_values import checked_setup


@rule("DAT022", "misspelled-data-folder", Severity.WARNING,
      fix="Name the folder under `share/<package>` like the source folder")
def misspelled_data_folder(package: Package) -> Iterator[Hit]:
    """data_files installs a folder's files into a folder whose name is a typo of it.

    ## What it does
    Reports a data_files destination `share/<package>/<folder>...` whose first folder after
    the package's share folder is a typo of the one folder all its sources come from (one
    edit, two for long names): `(os.path.join('share', package_name, 'lauch'),
    glob('launch/*.launch.py'))`. A plural and its singular (`model`, `models`) and names
    differing in a digit (`rviz`, `rviz2`) are not typos; destinations and sources not known
    statically are not compared.

    ## Why is this bad?
    The files are installed as `share/<package>/lauch/...`: a launch file including
    `PathJoinSubstitution([FindPackageShare('<package>'), 'launch', ...])`, a node reading
    `share/<package>/config/params.yaml` or an `IncludeLaunchDescription` of the source
    tree's layout fails with a missing file once installed (`ros2 launch <package> <file>`
    still finds a launch file: it searches the whole share folder by file name).

    ## Example
    ```python
    (os.path.join('share', package_name, 'lauch'), glob('launch/*.launch.py')),
    ```

    ## Use instead
    ```python
    (os.path.join('share', package_name, 'launch'), glob('launch/*.launch.py')),
    ```
    """
    setup = checked_setup(package)
    for entry in setup.data_file_entries if setup else ():
        parts = destination_parts(entry)
        folders = {posixpath.normpath(s.pattern.replace("\\", "/")).split("/")[0]
                   for s in entry.sources if "/" in s.pattern.replace("\\", "/")}
        if len(parts) < 3 or parts[:2] != ["share", package.name] or len(folders) != 1:
            continue
        folder, written = folders.pop(), parts[2]
        if written != folder and is_typo(written, folder) and \
                not digits_differ(written, folder) and \
                written.rstrip("s") != folder.rstrip("s") and "*" not in folder:
            found = "does not find them" if folder != "launch" else (
                "does not find them (`ros2 launch`, which searches the whole share folder "
                "by file name, does)")
            yield Hit(entry.span, f"data_files installs the files of `{folder}/` into "
                      f"`{entry.destination}`: `{written}` is a typo of `{folder}`, and "
                      f"whatever looks for them in `share/{package.name}/{folder}` {found}",
                      f"Install into `share/{package.name}/{folder}`")
