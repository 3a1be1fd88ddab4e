"""ENT004: the same console script name twice."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.registry import rule
from pkgtool.rules.setup_values import checked_setup


@rule("ENT004", "duplicate-console-script", Severity.WARNING,
      fix="Give each console script its own name, or remove the duplicate")
def duplicate_console_script(package: Package) -> Iterator[Hit]:
    """Two console scripts have the same command name.

    ## What it does
    Reports every `console_scripts` entry whose name an earlier entry already used.

    ## Why is this bad?
    Only one wrapper script can exist per name: one of the two commands silently replaces
    the other, so `ros2 run` starts a different node than the one the line promises.

    ## Example
    ```python
    'console_scripts': ['node = my_pkg.talker:main', 'node = my_pkg.listener:main']
    ```

    ## Use instead
    ```python
    'console_scripts': ['talker = my_pkg.talker:main', 'listener = my_pkg.listener:main']
    ```
    """
    setup = checked_setup(package)
    seen: dict[str, str] = {}
    for entry in setup.console_scripts if setup else ():
        if entry.name in seen:
            yield Hit(entry.span, f"Console script `{entry.name}` is already defined as "
                                  f"`{seen[entry.name]}`")
        else:
            seen[entry.name] = entry.spec
