"""DAT006: a file an installed launch file reads from share/<package> is not installed."""

from __future__ import annotations

import posixpath
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.installed import installed_data
from pkgtool.model.package import Package
from pkgtool.rules.registry import rule
from pkgtool.rules.setup_values import checked_setup


@rule("DAT006", "uninstalled-launch-resource", Severity.WARNING,
      fix="Install the file with data_files, e.g. `(os.path.join('share', package_name, "
          "'config'), glob('config/*.yaml'))`")
def uninstalled_launch_resource(package: Package) -> Iterator[Hit]:
    """An installed launch file uses a file of this package's share folder that is not installed.

    ## What it does
    For each launch file data_files installs, looks at the paths it builds from this
    package's share folder (`get_package_share_directory('<pkg>')`, `FindPackageShare`,
    `$(find-pkg-share <pkg>)` joined with static parts, e.g. `config/params.yaml`) and
    reports those that data_files does not install (neither the file nor a folder holding it).

    ## Why is this bad?
    The launch file starts, then fails on the missing parameter file, URDF or RViz config,
    or a node silently runs with default parameters.

    ## Example
    ```python
    params = os.path.join(get_package_share_directory('my_pkg'), 'config', 'params.yaml')
    # setup.py installs launch/ but not config/
    ```

    ## Use instead
    ```python
    (os.path.join('share', package_name, 'config'), glob('config/*.yaml')),
    ```
    """
    installed = installed_data(package) if checked_setup(package) else None
    if installed is None:
        return
    share = f"share/{package.name}"
    shared = {source for target, source in installed.items() if target.startswith(share + "/")}
    for launch in package.launch_files:
        if launch.path not in shared:
            continue
        for ref in launch.files:
            if ref.package != package.name or not ref.parts:
                continue
            target = posixpath.normpath(posixpath.join(share, *ref.parts))
            if target in installed or any(t.startswith(target + "/") for t in installed):
                continue
            relative = posixpath.relpath(target, share)
            yield Hit(ref.span, f"`{relative}` is not installed to `{share}`, but "
                                f"`{launch.path}` uses it")
