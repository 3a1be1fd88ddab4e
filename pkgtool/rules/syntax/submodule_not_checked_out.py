"""SYN005: a git submodule inside the package that is not checked out, so not checked."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule


@rule("SYN005", "submodule-not-checked-out", Severity.INFO,
      fix="Run `git submodule update --init --recursive`, then lint again")
def submodule_not_checked_out(package: Package) -> Iterator[Hit]:
    """A git submodule inside the package is not checked out, so what it holds went unchecked.

    ## What it does
    Notes each folder that the repository's `.gitmodules` lists inside the package and that
    holds no file: a clone made without `--recurse-submodules`. The files setup.py, launch
    files and `packages=[...]` name inside it are not reported missing (DAT001, DAT002,
    DAT012, SET011): they are missing from this checkout, not from the package.

    ## Why is this bad?
    It is not wrong in itself, but colcon cannot build the package from this checkout unless
    its setup.py fetches the submodule, and a clean lint does not vouch for the files in it.

    ## Example
    `.gitmodules` lists `my_pkg/common`, and `my_pkg/common/` is empty.

    ## Use instead
    `git submodule update --init --recursive` (or clone with `--recurse-submodules`).
    """
    where = "setup.py" if package.has_file("setup.py") else \
        "package.xml" if package.has_file("package.xml") else ""
    for folder in sorted(package.unfetched):
        yield Hit(Span(where), f"`{folder}` is a git submodule that is not checked out: the "
                               "files in it were not checked")
