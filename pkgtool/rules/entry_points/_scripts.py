"""What the ENT rules share: the script entry point groups, and what makes an entry malformed."""

from __future__ import annotations

from pkgtool.model.setup_py import EntryPoint

SCRIPT_GROUPS = ("console_scripts", "gui_scripts")


def problem(entry: EntryPoint) -> str | None:
    """What is wrong with a script entry point, or None when it is well-formed."""
    if "=" not in entry.spec:
        return "has no `=` between the command name and `module:function`"
    if not entry.name:
        return "has no command name before `=`"
    if any(c.isspace() for c in entry.name):
        return "has a command name with spaces"
    if not entry.valid:
        return "does not name a `module:function` of valid Python identifiers"
    if entry.attr is None:
        return "names a module but no function (`module:function`)"
    return None
