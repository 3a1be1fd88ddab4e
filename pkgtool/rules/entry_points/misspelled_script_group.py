"""ENT005: an entry point group that is a misspelling of ``console_scripts``."""

from __future__ import annotations

from collections.abc import Iterator
from difflib import get_close_matches

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.console_scripts import SCRIPT_GROUPS
from pkgtool.rules.registry import rule
from pkgtool.rules.setup_values import checked_setup


def misspelt(group: str) -> str | None:
    """The script group ``group`` is a misspelling of, or None."""
    if group in SCRIPT_GROUPS:
        return None
    normal = group.strip().lower().replace("-", "_").replace(" ", "_")
    found = get_close_matches(normal, SCRIPT_GROUPS, n=1, cutoff=0.8)
    return found[0] if found else None


@rule("ENT005", "misspelled-script-group", Severity.ERROR,
      fix="Name the group `console_scripts`")
def misspelled_script_group(package: Package) -> Iterator[Hit]:
    """An entry point group is a misspelling of `console_scripts`.

    ## What it does
    Reports `entry_points` groups in setup.py or setup.cfg that are not `console_scripts`
    or `gui_scripts` but nearly are (`console_script`, `Console_Scripts`,
    `console-scripts`). Other groups (plugins such as `ros2cli.command`) are left alone.

    ## Why is this bad?
    setuptools accepts any group name and records it as a plugin group: no executable is
    installed, the build succeeds, and `ros2 run` says "No executable found".

    ## Example
    ```python
    entry_points={'console_script': ['talker = my_pkg.talker:main']}
    ```

    ## Use instead
    ```python
    entry_points={'console_scripts': ['talker = my_pkg.talker:main']}
    ```
    """
    setup = checked_setup(package)
    seen: set[str] = set()
    for entry in setup.entry_points or () if setup else ():
        wanted = misspelt(entry.group)
        if wanted and entry.group not in seen:
            seen.add(entry.group)
            yield Hit(entry.span, f"`{entry.group}` is not `{wanted}`: setuptools installs no "
                                  f"executable from it")
    cfg = package.setup_cfg
    for option in cfg.options if cfg else ():
        wanted = misspelt(option.key) if option.section == "options.entry_points" else None
        if wanted:
            yield Hit(option.span, f"`{option.key}` is not `{wanted}`: setuptools installs no "
                                   f"executable from it")
