"""SET013: console scripts that install to bin/, on the shell's PATH, not for `ros2 run`."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.registry import rule
from pkgtool.rules.setup._ros2_run import is_rqt_plugin, meant_for_ros2_run, scripts_in_bin
from pkgtool.rules.setup_values import checked_setup


@rule("SET013", "console-scripts-on-path", Severity.INFO,
      fix="If `ros2 run` should start them, add `setup.cfg` with `[develop] "
          "script_dir=$base/lib/<package>` and `[install] install_scripts=$base/lib/<package>`")
def console_scripts_on_path(package: Package) -> Iterator[Hit]:
    """Console scripts install to `bin/` and nothing shows they are meant for `ros2 run`.

    ## What it does
    Notes the first `console_scripts` entry of a package whose scripts install to the prefix's
    `bin/` (no setup.cfg, or one without `[install] install_scripts`) when no evidence says
    they are nodes for `ros2 run`: no launch file of the package starts them, the README does
    not name `ros2 run <package>`, and no script's module imports rclpy's `Node`. That is
    right for a command-line tool (`ros2`, linters, code generators), so this is only
    information; with such evidence the package gets SET008 or SET009 (errors) instead.

    ## Why is this bad?
    It is not, for a tool meant for the shell. For a node it is: `ros2 run <package>
    <executable>` looks only in `lib/<package>/` and says "No executable found".

    ## Example
    ```text
    my_tool/setup.py   entry_points={'console_scripts': ['my_tool = my_tool.cli:main']}
    (no setup.cfg; my_tool/cli.py parses arguments and builds no node)
    ```

    ## Use instead
    ```ini
    # only if `ros2 run my_tool my_tool` should work:
    [develop]
    script_dir=$base/lib/my_tool
    [install]
    install_scripts=$base/lib/my_tool
    ```
    """
    setup = checked_setup(package)
    if setup is None or not scripts_in_bin(package) or is_rqt_plugin(package) or \
            meant_for_ros2_run(package):
        return
    yield Hit(setup.console_scripts[0].span,
              f"Console scripts install to `bin/` (on PATH): `ros2 run {package.name}` will not "
              f"find them, which is right for a command-line tool")
