"""LCH013: a launch file starts an executable of this package without naming the package."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.launch._executables import executables
from pkgtool.rules.registry import rule
from pkgtool.rules.setup_values import script_folder

PACKAGE_KEYS = {"Node": "package", "LifecycleNode": "package", "node": "pkg"}
"""The launch actions that start a ROS executable, each with the argument naming its package
(Python keyword; XML and YAML attribute)."""
_GIVEN = frozenset({"package", "pkg", "*", "**"})
"""Arguments that name the package, rightly or not (LCH005 reports ``pkg=`` in Python), or may
(unpacked ones)."""


def _scripts_in_library(package: Package) -> bool:
    """True when setup.cfg installs console scripts into ``lib/<package>`` (off ``PATH``)."""
    option = package.setup_cfg.get("install", "install_scripts") if package.setup_cfg else None
    return option is not None and script_folder(option.value) == f"$base/lib/{package.name}"


@rule("LCH013", "launch-node-without-package", Severity.ERROR,
      fix="Name the package: `Node(package='my_pkg', executable='talker')`")
def launch_node_without_package(package: Package) -> Iterator[Hit]:
    """A launch file starts an executable of this package but gives no package.

    ## What it does
    Reports a `Node()` or `LifecycleNode()` without `package=` (a `<node>` without `pkg=`)
    whose `executable` is a console script of this package, when setup.cfg installs those
    into `lib/<package>`. Calls that unpack `**kwargs` are not checked.

    ## Why is this bad?
    Without a package, launch_ros runs the executable as a plain command, looked up on
    `PATH`; ament_python packages install theirs in `lib/<package>`, which is never on
    `PATH`, so the launch fails with "executable 'talker' not found on the PATH".

    ## Example
    ```python
    Node(executable='talker', name='talker')
    ```

    ## Use instead
    ```python
    Node(package='my_pkg', executable='talker', name='talker')
    ```
    """
    known = executables(package)
    if not known or not _scripts_in_library(package):
        return
    for launch in package.launch_files:
        for node in launch.nodes:
            key = PACKAGE_KEYS.get(node.action)
            if key is None or _GIVEN & set(node.arguments) or node.executable not in known \
                    or node.unused:
                continue
            yield Hit(node.executable_span or node.span,
                      f"`{node.executable}` is started without `{key}=`: launch looks it up on "
                      f"PATH, but `{package.name}` installs it in `lib/{package.name}`, which "
                      "is not on PATH (\"executable not found\")",
                      f"Add `{key}='{package.name}'`" if key == "package" else
                      f'Add `{key}="{package.name}"`')
