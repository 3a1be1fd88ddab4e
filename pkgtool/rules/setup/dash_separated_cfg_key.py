"""SET010: dash-separated option names in setup.cfg."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.registry import rule

COMMANDS = frozenset({
    "develop", "install", "install_scripts", "install_lib", "install_data", "install_egg_info",
    "build", "build_py", "build_scripts", "build_ext", "egg_info", "sdist", "bdist_wheel",
    "bdist_egg", "easy_install", "dist_info", "editable_wheel", "aliases",
})
"""setuptools command sections (setuptools normalises only these, metadata and options)."""
FREE_SECTIONS = frozenset({"options.extras_require", "options.data_files",
                           "options.entry_points", "options.package_data",
                           "options.exclude_package_data"})
"""Sections whose keys are names chosen by the user, where dashes are fine."""


@rule("SET010", "dash-separated-cfg-key", Severity.WARNING,
      fix="Write the option with underscores, e.g. `script_dir`")
def dash_separated_cfg_key(package: Package) -> Iterator[Hit]:
    """A setuptools option in setup.cfg is written with dashes (`script-dir`).

    ## What it does
    Reports option names containing `-` in setup.cfg's `[metadata]`, `[options]` and
    setuptools command sections such as `[develop]` and `[install]`. Sections of other tools
    (`[flake8]`) and sections whose keys are user-chosen names are not checked.

    ## Why is this bad?
    setuptools deprecated dash-separated keys in 54.1 (2021) and warns on every build;
    setuptools 78.0.0 rejected them outright ("Invalid dash-separated key"), breaking builds,
    before 78.0.2 restored them for a while. Old ROS templates wrote `script-dir` and
    `install-scripts`.

    ## Example
    ```ini
    [develop]
    script-dir=$base/lib/my_pkg
    ```

    ## Use instead
    ```ini
    [develop]
    script_dir=$base/lib/my_pkg
    ```
    """
    cfg = package.setup_cfg
    if cfg is None:
        return
    for option in cfg.options:
        section = option.section
        setuptools_section = (section in COMMANDS or section == "metadata"
                              or section.startswith("options"))
        if "-" in option.key and setuptools_section and section not in FREE_SECTIONS:
            underscored = option.key.replace("-", "_")
            yield Hit(option.span, f"`{option.key}` is dash-separated, which setuptools "
                                   f"deprecates", f"Rename `{option.key}` to `{underscored}`")
