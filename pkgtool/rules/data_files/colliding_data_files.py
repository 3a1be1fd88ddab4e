"""DAT018: data_files installs two different files to the same path."""

from __future__ import annotations

import posixpath
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.installed import keyword_known
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule


@rule("DAT018", "colliding-data-files", Severity.ERROR,
      fix="Install each folder with an entry of its own (`('share/<pkg>/models/box', "
          "glob('models/box/*'))`), or build the entries with `os.walk`")
def colliding_data_files(package: Package) -> Iterator[Hit]:
    """data_files installs two different files of the package to the same path.

    ## What it does
    Reports each data_files source (a path or a glob) that installs a file to a path an
    earlier source of data_files already installs another file to: a data_files entry copies
    every file it lists straight into its destination folder, without the folders they came
    from, so `glob('worlds/**/*', recursive=True)` puts every `model.sdf` of every model
    folder at one path. Files whose contents are the same are left alone.

    ## Why is this bad?
    The file copied last replaces the others without a word: the installed package lacks
    files its source tree has (a model's `model.sdf`, a robot's `config/params.yaml`), and a
    `model://` lookup, a launch file or a node reads the wrong one or none.

    ## Example
    ```python
    (os.path.join('share', package_name, 'models'), glob('models/**/*', recursive=True)),
    ```

    ## Use instead
    ```python
    *[(os.path.join('share', package_name, folder), glob(f'{folder}/*.*'))
      for folder in ('models/box', 'models/table')],
    ```
    """
    setup = package.setup_py
    if setup is None or not keyword_known(package, "data_files"):
        return
    installed: dict[str, str] = {}
    for entry in setup.data_files or ():
        if entry.sources_is_text:
            continue
        for source in entry.sources:
            clashes = []
            for match in source.matches:
                if not package.has_file(match):
                    continue
                target = posixpath.normpath(posixpath.join(entry.destination,
                                                           posixpath.basename(match)))
                first = installed.setdefault(target, match)
                if first != match and not _same_text(package, first, match):
                    clashes.append((target, first, match))
            if clashes:
                yield _hit(source.span, source.pattern, clashes)


def _same_text(package: Package, one: str, other: str) -> bool:
    """True when both files were read and hold the same text."""
    first, second = package.texts.get(one), package.texts.get(other)
    return first is not None and first == second


def _hit(span: Span, pattern: str, clashes: list[tuple[str, str, str]]) -> Hit:
    target, first, match = clashes[0]
    more = f" (and {len(clashes) - 1} more files)" if len(clashes) > 1 else ""
    what = f"`{match}` is installed" if pattern == match else \
        f"`{pattern}` installs `{match}`"
    return Hit(span, f"{what} as `{target}`, where `{first}` is installed too{more}: "
               "data_files copies files without their folders, and the one copied last "
               "replaces the other")
