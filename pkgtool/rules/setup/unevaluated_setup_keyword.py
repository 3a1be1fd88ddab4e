"""SET012: a setup() keyword that lint cannot evaluate, so its checks are skipped."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.registry import rule
from pkgtool.rules.setup_values import checked_setup

CHECKED_KEYWORDS = {
    "packages": "installed modules", "package_dir": "installed modules",
    "py_modules": "installed modules", "data_files": "installed files",
    "entry_points": "console scripts", "name": "the name", "version": "the version",
    "**": "all keywords",
}
"""Keywords the SET, ENT and DAT rules read, and what is not checked without them."""


@rule("SET012", "unevaluated-setup-keyword", Severity.INFO,
      fix="Build the value from literals, `os.path.join`, `glob` and module-level names, or "
          "ignore this note")
def unevaluated_setup_keyword(package: Package) -> Iterator[Hit]:
    """A setup() keyword the checks rely on is computed by code lint does not run.

    ## What it does
    Notes `packages`, `package_dir`, `py_modules`, `data_files`, `entry_points`, `name` and
    `version` values (and `**kwargs`) that the static evaluator could not compute: reading
    files, `os.walk`, calls to functions it does not know, environment variables. The note
    points at the expression it stopped at. The checks that need the value say nothing (of a
    `data_files` list, the entries that evaluate are still checked one by one).

    ## Why is this bad?
    It is not wrong in itself: lint never runs setup.py, so it cannot vouch for what such
    code installs. Missing modules, launch files or resources then go unreported.

    ## Example
    ```python
    data_files=[(os.path.join('share', package_name, root), [os.path.join(root, f)])
                for root, _, files in os.walk('models') for f in files]
    ```

    ## Use instead
    ```python
    data_files=[(os.path.join('share', package_name, 'models'), glob('models/*.sdf'))]
    ```
    """
    setup = checked_setup(package)
    reported: set[str] = set()
    for keyword, unresolved in setup.unresolved if setup else ():
        if keyword in CHECKED_KEYWORDS and keyword not in reported:
            reported.add(keyword)
            shown = "`**` keywords" if keyword == "**" else f"`{keyword}`"
            skipped = f"checks of {CHECKED_KEYWORDS[keyword]} are skipped"
            if keyword == "data_files" and setup.data_files_in_part:
                count = len(setup.data_files_in_part)
                skipped = (f"checks of what the list installs as a whole are skipped (its "
                           f"{count} {'entry' if count == 1 else 'entries'} that evaluate are "
                           "checked one by one)")
            yield Hit(unresolved.span, f"{shown} could not be evaluated statically "
                                       f"(`{unresolved.source}`): {skipped}")
