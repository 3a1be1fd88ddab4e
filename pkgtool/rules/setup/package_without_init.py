"""SET015: packages= lists a folder that has no __init__.py."""

from __future__ import annotations

import posixpath
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.registry import rule
from pkgtool.rules.setup_values import listed_packages


@rule("SET015", "package-without-init", Severity.WARNING,
      fix="Add an empty `__init__.py` to the folder")
def package_without_init(package: Package) -> Iterator[Hit]:
    """`packages=[...]` lists a folder that has no `__init__.py`.

    ## What it does
    For an explicit `packages` list, maps each name to its folder the way setuptools does
    (respecting `package_dir`) and reports an existing folder without an `__init__.py`. A
    missing folder is SET011.

    ## Why is this bad?
    setuptools warns "package init file ... not found", and the installed folder is an
    implicit namespace package: it merges with any other folder of that name on `sys.path`,
    and moving to `find_packages()` later silently drops it (and every subpackage below it)
    from the install.

    ## Example
    ```text
    setup.py           # packages=['demo']
    demo/talker.py     # no demo/__init__.py
    ```

    ## Use instead
    ```text
    demo/__init__.py   # empty
    demo/talker.py
    ```
    """
    for name, folder, span in listed_packages(package):
        init = posixpath.join(folder, "__init__.py")
        if folder and not package.has_file(init) and \
                any(f.startswith(folder + "/") for f in package.files):
            yield Hit(span, f"`packages` lists `{name}`, but `{init}` does not exist")
