"""DAT001: a data_files source that does not exist."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.lazy_regex import lazy_pattern
from pkgtool.model.package import Package
from pkgtool.model.setup_eval.tree import normalize
from pkgtool.model.submodules import under
from pkgtool.rules.registry import rule
from pkgtool.rules.setup_values import checked_setup


_GENERATORS = lazy_pattern(r"\bsubprocess\b|\bos\.system\s*\(|\bcheck_call\s*\(")
"""What a setup.py running a program (xacro, a generator) before ``setup()`` calls: the
files it writes exist once it has run."""


@rule("DAT001", "missing-data-file", Severity.ERROR,
      fix="Create the file, fix its path (relative to setup.py), or remove it from data_files")
def missing_data_file(package: Package) -> Iterator[Hit]:
    """A file listed in data_files does not exist.

    ## What it does
    Reports literal (non-glob) data_files sources that are not files of the package, and
    sources given as one string instead of a list (setuptools reads each character as a file
    name). Paths are relative to setup.py's folder, as colcon runs it. Absolute paths and
    folders (see DAT007) are not reported here, nor missing files of a setup.py that runs a
    program (`subprocess`, `os.system`: it may write them before `setup()`). When some item
    of a `data_files` list cannot be evaluated statically (`os.walk`), the items that can
    are still checked.

    ## Why is this bad?
    The build stops with "error: can't copy 'x': doesn't exist or not a regular file".

    ## Example
    ```python
    data_files=[('share/my_pkg', ['package.xml', 'config/param.yaml']),
                ('share/my_pkg/launch', 'launch/demo.launch.py')]
    ```

    ## Use instead
    ```python
    data_files=[('share/my_pkg', ['package.xml', 'config/params.yaml']),
                ('share/my_pkg/launch', ['launch/demo.launch.py'])]
    ```
    """
    setup = checked_setup(package)
    generates = _GENERATORS.search(package.texts.get("setup.py", "")) is not None
    for entry in setup.data_file_entries if setup else ():
        for source in entry.sources:
            if entry.sources_is_text:
                yield Hit(source.span, f"The sources of `{entry.destination}` are the string "
                                       f"`{source.pattern}`, not a list: setuptools installs "
                                       "each character as a file",
                          f"Write `['{source.pattern}']`")
                continue
            path = normalize(source.pattern)
            if source.is_glob or source.matches or path is None or package.has_folder(path) \
                    or under(path, package.unfetched) or generates:
                continue
            yield Hit(source.span, f"`{source.pattern}` does not exist (data_files for "
                                   f"`{entry.destination}`)")
