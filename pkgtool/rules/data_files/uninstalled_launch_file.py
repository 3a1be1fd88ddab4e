"""DAT005: a launch file that is not installed under share/<package>."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.installed import installed_data
from pkgtool.model.launch import (in_launch_folder, is_launch_file, is_launch_test,
                                  nested_packages, named_like_launch_only, python_folders,
                                  runs_as_launch_file)
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule
from pkgtool.rules.setup_values import checked_setup
from pkgtool.lazy_regex import lazy_pattern

NOT_INSTALLED_FOLDERS = frozenset({"test", "tests", "doc", "docs", "docker", ".devcontainer"})
"""Top-level folders whose launch files are test or documentation material, or what a
container image copies in and runs by its path (``ros2 launch /ws/server.launch.py``)."""


@rule("DAT005", "uninstalled-launch-file", Severity.ERROR,
      fix="Add `(os.path.join('share', package_name, 'launch'), glob('launch/*launch.*'))` to "
          "data_files")
def uninstalled_launch_file(package: Package) -> Iterator[Hit]:
    """A launch file of the package is not installed under `share/<package>`.

    ## What it does
    Reports launch files (`*.launch.py`, `*_launch.py`, XML and YAML variants, and any Python
    file of a `launch` folder defining `generate_launch_description`: `launch/launch.py`) that
    data_files does not install anywhere under `share/<name>`; installing them flat into
    `share/<name>` or into `share/<name>/launch` are both fine. Launch files under `test/`,
    `doc/`, `docker/` and `.devcontainer/` (a container runs them by their path) are
    ignored, and so are files that only look like launch files: outside a
    `launch` folder, a module inside the Python package, a `test_*` file or a file under
    `examples/` or `samples/`, files under a sub-folder with a package.xml of its own (that
    package's), and a
    `launch_testing` test kept in a `launch` folder (it defines `generate_test_description`
    and no `generate_launch_description`: `ros2 launch` cannot run it), and a copy of a
    launch file whose name an installed one has (`ros2 launch` finds that one), or one
    named as kept aside (`robot_launch_old.py`, `controller_launch(discarded).py`).

    ## Why is this bad?
    `ros2 launch <package> <file>` searches the installed share folder only: the launch file
    works from the source tree but "file not found" after every build.

    ## Example
    ```python
    data_files=[('share/' + package_name, ['package.xml'])]   # launch/robot.launch.py exists
    ```

    ## Use instead
    ```python
    data_files=[
        ('share/' + package_name, ['package.xml']),
        (os.path.join('share', package_name, 'launch'), glob('launch/*.launch.py')),
    ]
    ```
    """
    installed = installed_data(package) if checked_setup(package) else None
    if installed is None:
        return
    share = f"share/{package.name}/"
    shared = {source for target, source in installed.items() if target.startswith(share)}
    names = {target.rsplit("/", 1)[-1] for target in installed if target.startswith(share)}
    folders, nested = python_folders(package.files), nested_packages(package.files)
    for path in sorted({*(f for f in package.files if is_launch_file(f, folders, nested) and
                          not is_launch_test(f, package.texts.get(f)) and
                          not named_like_launch_only(f, package.texts.get(f))),
                        *(launch.path for launch in package.launch_files),
                        *_launch_by_content(package, folders, nested)}):
        name = path.rsplit("/", 1)[-1]
        if path.split("/")[0] not in NOT_INSTALLED_FOLDERS and path not in shared and \
                name not in names and not _KEPT_ASIDE.search(name.rsplit(".", 1)[0]):
            yield Hit(Span(path, 1, 1), f"`{path}` is not installed under `{share[:-1]}`: "
                                        f"`ros2 launch {package.name} {name}` will not find it")


_KEPT_ASIDE = lazy_pattern(r"(?i)(?:^|[_.\- (\[])(?:old|orig|original|copy|backup|bak|unused|"
                           r"deprecated|discarded|obsolete|legacy)(?:[_.\- )\]]|\d|$)")
"""A copy kept aside by its name (``flow.launch_original.py``, ``ctrl_launch-Copy1.py``,
``controller_launch(discarded).py``)."""


def _launch_by_content(package: Package, folders: frozenset[str], nested: frozenset[str]
                       ) -> Iterator[str]:
    """Python files of a ``launch`` folder (not a Python package's, a template's or a nested
    package's) that define ``generate_launch_description`` whatever their name
    (``launch/launch.py``, ``launch/debugging.py``), unless named as a copy kept aside."""
    for path in package.files:
        folder, _, name = path.rpartition("/")
        if path.endswith(".py") and in_launch_folder(path, nested) and folder not in folders \
                and not _KEPT_ASIDE.search(name[:-3]) and \
                runs_as_launch_file(path, package.texts.get(path, "")):
            yield path
