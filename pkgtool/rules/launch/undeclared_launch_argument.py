"""LCH029: a launch file reads a launch configuration nothing declares, sets or gives it."""

from __future__ import annotations

import posixpath
import re
from collections.abc import Iterator
from difflib import get_close_matches

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.launch._python_launch import READ_BY_LAUNCH, reads_shown, undeclared_reads
from pkgtool.rules.launch_includes import own_includes
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import launch_indexes


@rule("LCH029", "undeclared-launch-argument", Severity.WARNING,
      fix="Declare it (`DeclareLaunchArgument('<name>', default_value=...)`, "
          "`<arg name=\"<name>\" default=\"...\"/>`), or give the read a default")
def undeclared_launch_argument(package: Package) -> Iterator[Hit]:
    """A launch file reads a launch configuration that nothing declares, sets or hands it.

    ## What it does
    Reports `LaunchConfiguration('x')` without a `default` (Python launch files) and
    `$(var x)` (XML and YAML ones) when no launch file of the package declares `x`
    (`DeclareLaunchArgument`, `<arg>`, `<let>`), the reading file names `x` nowhere else
    (`SetLaunchConfiguration`, a condition), no other launch file of the package names it
    (quoted, as an `<arg>` name, in a `$(var x)`: an include handing it on), no launch file
    of the package includes the reading file or names it (its includer may hand `x` on),
    and `x` is spelled like no declared argument of the file (LCH008 reports those). Python
    launch files that may declare or set arguments where the file does not show it are left
    alone (as LCH024 leaves them: helpers of other modules, an `OpaqueFunction`, includes).
    `launch-prefix` and `emulate_tty`, which launch reads itself, are left alone.

    ## Why is this bad?
    `ros2 launch my_pkg robot.launch.py` stops with `launch configuration 'x' does not
    exist` unless the user happens to type `x:=...`; and `--show-args` does not list `x`, so
    nothing tells them to. A file another package includes works only while that package
    keeps handing `x` on. This is a warning: the author may mean `x:=` to be required.

    ## Example
    ```python
    return LaunchDescription([
        Node(package='my_robot', executable='driver',
             parameters=[{'port': LaunchConfiguration('serial_port')}]),
    ])
    ```

    ## Use instead
    ```python
    return LaunchDescription([
        DeclareLaunchArgument('serial_port', default_value='/dev/ttyUSB0'),
        Node(package='my_robot', executable='driver',
             parameters=[{'port': LaunchConfiguration('serial_port')}]),
    ])
    ```
    """
    included = {include.target for include in own_includes(package)}
    texts = {launch.path: package.texts.get(launch.path, "") for launch in package.launch_files}
    hidden = {path for path, index in launch_indexes(package) if not reads_shown(index)}
    for span, name, declared in undeclared_reads(package):
        others = [text for path, text in texts.items() if path != span.path]
        if span.path in included | hidden or name in READ_BY_LAUNCH or \
                get_close_matches(name, sorted(declared), n=1, cutoff=0.8) or \
                any(posixpath.basename(span.path) in text or _names(text, name)
                    for text in others):
            continue  # set by an includer, or named elsewhere
        yield Hit(span, f"The launch configuration `{name}` is read, but no launch file of the "
                        f"package declares or sets it: the launch stops with launch "
                        f"configuration '{name}' does not exist unless `{name}:=...` is given")


def _names(text: str, name: str) -> bool:
    """True when a launch file's ``text`` names the configuration ``name``: quoted (a
    declaration, ``launch_arguments``), as ``name="x"`` or ``name: x`` (an XML or YAML
    ``<arg>``), or read by ``$(var x)``."""
    return re.search(rf"""['"]{re.escape(name)}['"]|\bname:\s*{re.escape(name)}\s*$|"""
                     rf"""\$\(var\s+{re.escape(name)}\s*\)""", text, re.M) is not None
