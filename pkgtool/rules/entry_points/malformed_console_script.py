"""ENT001: a console_scripts entry that does not parse as `name = module:function`."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.console_scripts import SCRIPT_GROUPS, problem
from pkgtool.rules.registry import rule
from pkgtool.rules.setup_values import checked_setup


@rule("ENT001", "malformed-console-script", Severity.ERROR,
      fix="Write the entry as `command = package.module:function`")
def malformed_console_script(package: Package) -> Iterator[Hit]:
    """A console script entry point is not `name = module:function`.

    ## What it does
    Parses each `console_scripts` (and `gui_scripts`) entry the way setuptools does and
    reports entries without `=`, without a command name, with a module or function path
    that is not dotted words of letters, digits and underscores (`my-pkg.node`), or without
    the `:function` part. Parts need not be Python identifiers: the wrapper setuptools
    installs loads `pkg.96:main` with `importlib`, which works; nor need the command name
    be one word (`MAP EXPLORER` installs as `lib/<package>/MAP EXPLORER`, which launch_ros
    starts).

    ## Why is this bad?
    setuptools rejects unparsable entries and the build fails; an entry without `:function`
    installs a wrapper that calls the module object and fails at run time.

    ## Example
    ```python
    entry_points={'console_scripts': ['talker = my_pkg.talker.main',
                                      'listener = my-pkg.listener:main']}
    ```

    ## Use instead
    ```python
    entry_points={'console_scripts': ['talker = my_pkg.talker:main',
                                      'listener = my_pkg.listener:main']}
    ```
    """
    setup = checked_setup(package)
    for entry in setup.entry_points or () if setup else ():
        if entry.group in SCRIPT_GROUPS:
            reason = problem(entry)
            if reason:
                yield Hit(entry.span, f"Console script `{entry.spec}` {reason}")
