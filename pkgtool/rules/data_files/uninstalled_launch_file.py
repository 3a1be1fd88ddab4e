"""DAT005: a launch file that is not installed under share/<package>."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.cmake_install import installed_into_share
from pkgtool.model.installed import cmake_text, installed_data, is_ament_python
from pkgtool.model.launch import (in_launch_folder, is_launch_file, is_launch_test, kept_aside,
                                  nested_packages, named_like_launch_only, python_folders,
                                  runs_as_launch_file)
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule
from pkgtool.rules.setup_values import checked_setup, name_cause, setup_alias

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
    named as kept aside (`robot_launch_old.py`, `controller_launch(discarded).py`). In a
    package built with CMake, reports the launch files that no `install(DIRECTORY|FILES ...
    DESTINATION share/${PROJECT_NAME}...)` (nor `ament_auto_package(INSTALL_TO_SHARE ...)`)
    names, with their folder or alone, when every command of CMakeLists.txt is one whose
    effect is known (a macro of another package may install them).

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
    if not is_ament_python(package):
        yield from _not_installed_by_cmake(package)
        return
    installed = installed_data(package) if checked_setup(package) else None
    if installed is None:
        return
    share = f"share/{package.name}/"
    shared = {source for target, source in installed.items() if target.startswith(share)}
    names = {target.rsplit("/", 1)[-1] for target in installed if target.startswith(share)}
    alias = setup_alias(package)
    aliased = {source for target, source in installed.items()
               if alias and target.startswith(f"share/{alias}/")}
    for path in _launch_files(package):
        name = path.rsplit("/", 1)[-1]
        if path not in shared and name not in names:
            yield Hit(Span(path, 1, 1), f"`{path}` is not installed under `{share[:-1]}`: "
                                        f"`ros2 launch {package.name} {name}` will not find it",
                      cause=name_cause(alias) if path in aliased else "",
                      consequence=path in aliased)


def _not_installed_by_cmake(package: Package) -> Iterator[Hit]:
    """The launch files of a package built with CMake that no ``install()`` puts under
    ``share/<package>`` (when what its CMakeLists.txt installs there is known)."""
    text = cmake_text(package) if package.has_file("package.xml") else None
    installed = installed_into_share(text, package.files) if text is not None else None
    if installed is None:
        return
    for path in _launch_files(package):
        if not any(folder in ("", ".") or path == folder or path.startswith(folder + "/")
                   for folder in installed):
            folder, _, name = path.rpartition("/")
            install = f"DIRECTORY {folder.split('/')[0]}" if folder else f"FILES {path}"
            yield Hit(Span(path, 1, 1), f"`{path}` is not installed under `share/"
                      f"{package.name}`: no `install()` of CMakeLists.txt names it or its folder,"
                      f" so `ros2 launch {package.name} {name}` will not find it",
                      f"Add `install({install} DESTINATION share/${{PROJECT_NAME}})` to "
                      "CMakeLists.txt")


def _launch_files(package: Package) -> list[str]:
    """The package's launch files a user may ``ros2 launch``, in path order: not those of
    :data:`NOT_INSTALLED_FOLDERS`, nor copies kept aside."""
    folders, nested = python_folders(package.files), nested_packages(package.files)
    found = {*(f for f in package.files if is_launch_file(f, folders, nested, package.name) and
               not is_launch_test(f, package.texts.get(f)) and
               not named_like_launch_only(f, package.texts.get(f))),
             *(launch.path for launch in package.launch_files),
             *_launch_by_content(package, folders, nested)}
    return sorted(path for path in found if path.split("/")[0] not in NOT_INSTALLED_FOLDERS and
                  not kept_aside(path))


def _launch_by_content(package: Package, folders: frozenset[str], nested: frozenset[str]
                       ) -> Iterator[str]:
    """Python files of a ``launch`` folder (not a Python package's, a template's or a nested
    package's) that define ``generate_launch_description`` whatever their name
    (``launch/launch.py``, ``launch/debugging.py``), unless named as a copy kept aside."""
    for path in package.files:
        folder, _, name = path.rpartition("/")
        if path.endswith(".py") and in_launch_folder(path, nested) and folder not in folders \
                and not kept_aside(path) and \
                runs_as_launch_file(path, package.texts.get(path, "")):
            yield path
