"""PYC061: a console script's module calls its entry function at import time."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.imports import entry_points_installed
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import FUNCTIONS, Index, installed_trees

EXITS = frozenset({"sys.exit"})
"""What a module may wrap its entry function's call in (``sys.exit(main())``), besides the
builtins ``exit`` and ``quit``."""


def _called(statement: ast.stmt, index: Index) -> ast.Call | None:
    """The call a top-level statement makes of a plain name: ``main()``, or the one inside
    ``sys.exit(main())``."""
    call = statement.value if isinstance(statement, ast.Expr) else None
    if isinstance(call, ast.Call) and (index.qualified(call.func) in EXITS or isinstance(
            call.func, ast.Name) and call.func.id in ("exit", "quit")) and call.args:
        call = call.args[0]
    return call if isinstance(call, ast.Call) and isinstance(call.func, ast.Name) else None


@rule("PYC061", "main-called-at-import", Severity.ERROR,
      fix="Call it only when the file runs as a script: `if __name__ == '__main__': main()`")
def main_called_at_import(package: Package) -> Iterator[Hit]:
    """A console script's module calls its entry function when it is imported.

    ## What it does
    Reports a top-level statement `main()` (or `sys.exit(main())`) in a module a console
    script of setup.py runs, when `main` is the function that console script names and the
    module defines it, outside `if __name__ == '__main__':`.

    ## Why is this bad?
    The console script `ros2 run` starts imports the module and then calls the function. The
    import already runs the node; once it ends (Ctrl-C), the script calls `main()` again and
    starts a second run. A test that imports the module to reach its node class never gets
    past the import: it hangs until the test times out.

    ## Example
    ```python
    def main():
        rclpy.init()
        rclpy.spin(Talker())

    main()
    ```

    ## Use instead
    ```python
    def main():
        rclpy.init()
        rclpy.spin(Talker())

    if __name__ == '__main__':
        main()
    ```
    """
    entries: dict[str, dict[str, str]] = {}
    for entry, path in entry_points_installed(package, "console_scripts"):
        if entry.attr:
            entries.setdefault(path, {})[entry.attr] = entry.name
    for module, tree, index in installed_trees(package):
        scripts = entries.get(module.path)
        if not scripts:
            continue
        defined = {f.name for f in tree.body if isinstance(f, FUNCTIONS)}
        for statement in tree.body:
            call = _called(statement, index)
            name = call.func.id if call is not None else ""  # type: ignore[attr-defined]
            if call is not None and name in scripts and name in defined:
                yield Hit(Span(module.path, call.lineno, call.col_offset + 1),
                          f"`{name}()` runs when the module is imported: the console script "
                          f"`{scripts[name]}` imports it (so the node runs) and then calls "
                          f"`{name}()` again, and a test importing the module never returns")
