"""ENT003: a console script whose function the module does not define."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.console_scripts import scripts_and_modules
from pkgtool.rules.registry import rule


@rule("ENT003", "undefined-entry-point-function", Severity.ERROR,
      fix="Define the function at the module's top level, or point the entry at the right one")
def undefined_entry_point_function(package: Package) -> Iterator[Hit]:
    """A console script names a function its module does not define at top level.

    ## What it does
    For console scripts whose module is installed and parses, checks that the first part of
    `:function` is defined at the module's top level (a `def`, a class, an assignment or an
    import). Modules with `from x import *` or a module-level `__getattr__` are skipped.

    ## Why is this bad?
    The build succeeds, but running the command fails with `AttributeError` (or `ImportError`
    in the generated wrapper), often only after deployment.

    ## Example
    ```python
    # setup.py: 'talker = my_pkg.talker:main'
    def run():          # my_pkg/talker.py defines run, not main
        ...
    ```

    ## Use instead
    ```python
    def main():
        ...
    ```
    """
    entries, modules = scripts_and_modules(package)
    for entry in entries:
        if entry.module not in modules:
            continue
        module = package.module(modules[entry.module])
        if module is None or module.syntax_error or "__getattr__" in module.top_level_names:
            continue
        if any("*" in i.names for i in module.imports):
            continue
        function = (entry.attr or "").split(".")[0]
        if function not in module.top_level_names:
            yield Hit(entry.span, f"`{entry.module}` does not define `{function}` at its top "
                                  f"level (`{modules[entry.module]}`)")
