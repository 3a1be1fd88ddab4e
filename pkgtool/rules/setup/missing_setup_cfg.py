"""SET008: console scripts without setup.cfg's script folders."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.installed import installed_data
from pkgtool.model.package import Package
from pkgtool.rules.registry import rule
from pkgtool.rules.setup._ros2_run import is_rqt_plugin, meant_for_ros2_run
from pkgtool.rules.setup_values import checked_setup


@rule("SET008", "missing-setup-cfg", Severity.ERROR,
      fix="Add `setup.cfg` with `[develop] script_dir=$base/lib/<package>` and `[install] "
          "install_scripts=$base/lib/<package>`")
def missing_setup_cfg(package: Package) -> Iterator[Hit]:
    """The package has console scripts but no setup.cfg.

    ## What it does
    Reports the first `console_scripts` entry of a package that has no setup.cfg, when the
    scripts are meant for `ros2 run`: a launch file of the package starts one, the README
    names `ros2 run <package>`, or a script's module imports rclpy's `Node`. Command-line tools
    (`ros2`, linters, code generators) install to `bin/` on purpose; without such evidence
    the package gets SET013 (info) instead. An rqt plugin (package.xml exports `<rqt_gui
    plugin=...>`) is exempt: rqt tools install their standalone script to `bin/` on purpose,
    so that `rqt_graph` runs without `ros2 run`, and so is a package whose data_files install
    an executable of each script's name into `lib/<package>` (wrapper scripts kept in
    the source tree: `ros2 run` finds those).

    ## Why is this bad?
    Without `script_dir`/`install_scripts`, setuptools installs the executables into the
    prefix's `bin/` folder. `ros2 run` and launch files look only in `lib/<package>/`, so
    they report "No executable found" although the build succeeded.

    ## Example
    ```text
    my_robot/setup.py    entry_points={'console_scripts': ['talker = my_robot.talker:main']}
    (no setup.cfg)
    ```

    ## Use instead
    ```ini
    [develop]
    script_dir=$base/lib/my_robot
    [install]
    install_scripts=$base/lib/my_robot
    ```
    """
    setup = checked_setup(package)
    if setup is None or package.has_file("setup.cfg") or not setup.console_scripts:
        return
    if is_rqt_plugin(package) or not meant_for_ros2_run(package):
        return
    installed = installed_data(package) or {}
    if all(f"lib/{package.name}/{script.name}" in installed for script in setup.console_scripts):
        return  # data_files installs an executable of each name where `ros2 run` looks
    yield Hit(setup.console_scripts[0].span,
              f"Without `setup.cfg` console scripts install to `bin/`, where `ros2 run "
              f"{package.name}` does not look")
