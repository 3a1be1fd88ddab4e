"""SET009: setup.cfg's script folders are not lib/<this package>."""

from __future__ import annotations

from collections.abc import Iterator
from difflib import get_close_matches

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.setup_cfg import CfgOption
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule
from pkgtool.rules.setup._ros2_run import meant_for_ros2_run
from pkgtool.rules.setup_values import checked_setup, name_cause, script_folder

SCRIPT_OPTIONS = (("develop", "script_dir"), ("install", "install_scripts"))


def near_miss(options: tuple[CfgOption, ...], section: str, key: str) -> CfgOption | None:
    """A misspelt key in the right section, or the right key in a misspelt section."""
    for option in options:
        same_key = option.key.replace("-", "_") == key
        if (option.section == section and not same_key and
                get_close_matches(option.key, [key], cutoff=0.8)) or \
                (same_key and get_close_matches(option.section, [section], cutoff=0.7)):
            return option
    return None


@rule("SET009", "wrong-script-dir", Severity.ERROR,
      fix="Set `[develop] script_dir` and `[install] install_scripts` to `$base/lib/<package>`")
def wrong_script_dir(package: Package) -> Iterator[Hit]:
    """setup.cfg sends console scripts somewhere other than `lib/<this package>`.

    ## What it does
    Checks `[develop] script_dir` and `[install] install_scripts` in setup.cfg: each must be
    `$base/lib/<name>` with this package's name. A missing option is reported at a misspelt
    key (`install_script`) or section (`[instal]`) when there is one, else when the package
    has console scripts meant for `ros2 run` (see SET008 for the evidence; a command-line
    tool whose setup.cfg holds only other sections gets SET013, info). A wrong value is
    reported when setup.py installs scripts; a folder below `lib/<name>`
    (`$base/lib/<name>/scripts`) only when a launch file of the package starts one of them,
    as `ros2 run` searches below `lib/<name>` and launch_ros does not.

    ## Why is this bad?
    `ros2 run <package> <executable>` and launch files look for executables only in
    `lib/<package>/`. A folder named after another package (a copied setup.cfg) or a missing
    option (executables land in `bin/`) makes them "No executable found". `script_dir` is used
    by `colcon build --symlink-install`, `install_scripts` by a plain `colcon build`.

    ## Example
    ```ini
    [develop]
    script_dir=$base/lib/turtle_demo
    [install]
    install_scripts=$base/lib/turtle_demo
    ```

    ## Use instead
    ```ini
    [develop]
    script_dir=$base/lib/my_pkg
    [install]
    install_scripts=$base/lib/my_pkg
    ```
    """
    setup, cfg = checked_setup(package), package.setup_cfg
    if setup is None or cfg is None:
        return
    wanted = f"$base/lib/{package.name}"
    for section, key in SCRIPT_OPTIONS:
        option = cfg.get(section, key)
        if option is None:
            near = near_miss(cfg.options, section, key)
            if near is not None:
                yield Hit(near.span, f"`[{near.section}] {near.key}` is not `[{section}] {key}`: "
                                     f"console scripts install to `bin/`, not "
                                     f"`lib/{package.name}`", f"Write `[{section}] {key}`")
            elif setup.console_scripts and meant_for_ros2_run(package):
                yield Hit(Span(cfg.path, 1, 1),
                          f"`setup.cfg` has no `[{section}] {key}`: console scripts install to "
                          f"`bin/`, not `lib/{package.name}`")
        elif script_folder(option.value) != wanted and _scripts(package):
            inside = script_folder(option.value).startswith(wanted + "/")
            if inside and not _launched(package):
                continue  # `ros2 run` walks lib/<package> down; only launch_ros does not
            yield Hit(option.span, f"`{option.key}` is `{option.value}`, not `{wanted}`: "
                                   + (f"launch_ros looks for executables in `lib/{package.name}` "
                                      "itself, not below it: the launch file's nodes will not "
                                      "start" if inside else
                                      f"`ros2 run {package.name}` will not find the "
                                      "executables"),
                      cause=name_cause(script_folder(option.value).rpartition("/lib/")[2]),
                      consequence=True)


def _scripts(package: Package) -> bool:
    """True when setup.py installs scripts (console scripts, or ``scripts=``), or may."""
    setup = package.setup_py
    return setup is None or bool(setup.console_scripts) or "scripts" in setup.keywords or \
        setup.is_unresolved("entry_points") or setup.is_unresolved("**")


def _launched(package: Package) -> bool:
    """True when a launch file of the package starts one of its own console scripts."""
    setup = package.setup_py
    names = {entry.name for entry in setup.console_scripts} if setup else set()
    return any(node.package == package.name and node.executable in names
               for launch in package.launch_files for node in launch.nodes)
