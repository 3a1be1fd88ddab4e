"""DAT006: a file an installed launch file reads from share/<package> is not installed."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.data_files.common import uninstalled_launch_resources
from pkgtool.rules.registry import rule


@rule("DAT006", "uninstalled-launch-resource", Severity.ERROR,
      fix="Install the file with data_files, e.g. `(os.path.join('share', package_name, "
          "'config'), glob('config/*.yaml'))`")
def uninstalled_launch_resource(package: Package) -> Iterator[Hit]:
    """An installed launch file or module uses a file of the package's share it does not install.

    ## What it does
    For each launch file data_files installs, and each installed module that imports
    `ament_index_python`, looks at the paths it builds from this package's share folder
    (`get_package_share_directory('<pkg>')`, `FindPackageShare`, `$(find-pkg-share <pkg>)`
    joined with static parts, e.g. `config/params.yaml`) and reports those that data_files
    does not install (neither the file nor a folder holding it) while the package has them.
    A file the package does not have at all is DAT012's. Paths that are glob patterns
    (`config/*.yaml`) count when installed files match them, and a module that asks whether
    files exist (`os.path.exists`, `Path.exists()`: it handles a missing one) is left alone;
    in a launch file only the paths it asks that of are (all of them when it asks of a path
    pkgtool cannot work out). A folder holding only hidden files (`output/.gitkeep`: where
    the code writes) has nothing to install.

    ## Why is this bad?
    The launch file starts, then fails on the missing parameter file, URDF or RViz config,
    or a node silently runs with default parameters; a node reading the file dies with
    `FileNotFoundError` once installed, though it worked from the source tree.

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
    share = f"share/{package.name}"
    for reader, ref, relative, _ in uninstalled_launch_resources(package):
        if package.has_file(relative) or package.has_folder(relative) and \
                not _placeholder_folder(package, relative):
            yield Hit(ref.span, f"`{relative}` is not installed to `{share}`, but "
                                f"`{reader}` uses it")


def _placeholder_folder(package: Package, path: str) -> bool:
    """True for a folder holding only hidden files (``output/.gitkeep``): kept in git for
    what the code writes there, nothing to install."""
    prefix = path.rstrip("/") + "/"
    return all(f.rpartition("/")[2].startswith(".") for f in package.files
               if f.startswith(prefix))
