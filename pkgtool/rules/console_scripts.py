"""What the ENT rules share: the script groups, malformed entries, entries worth checking."""

from __future__ import annotations

from pkgtool.model.installed import installed_modules
from pkgtool.model.package import Package
from pkgtool.model.setup_py import EntryPoint
from pkgtool.rules.setup_values import checked_setup

SCRIPT_GROUPS = ("console_scripts", "gui_scripts")


def problem(entry: EntryPoint) -> str | None:
    """What is wrong with a script entry point, or None when it is well-formed."""
    if "=" not in entry.spec:
        return "has no `=` between the command name and `module:function`"
    if not entry.name:
        return "has no command name before `=`"
    if not entry.valid:
        return "does not name a `module:function` of letters, digits and underscores"
    if entry.attr is None:
        return "names a module but no function (`module:function`)"
    return None


def scripts_and_modules(package: Package) -> tuple[list[EntryPoint], dict[str, str]]:
    """Well-formed script entries of a checked setup.py, and the modules it installs.

    Nothing when setup.py is not checked or what it installs is not known statically.
    """
    setup = checked_setup(package)
    modules = installed_modules(package) if setup else None
    if setup is None or modules is None:
        return [], {}
    return [e for e in setup.entry_points or ()
            if e.group in SCRIPT_GROUPS and not problem(e)], modules
