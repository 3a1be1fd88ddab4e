"""DAT007: a folder given as a data_files source."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.setup_eval.tree import normalize
from pkgtool.rules.registry import rule
from pkgtool.rules.setup_values import checked_setup


@rule("DAT007", "directory-data-source", Severity.ERROR,
      fix="List the folder's files (e.g. `glob('config/*.yaml')`), one data_files entry per "
          "sub-folder")
def directory_data_source(package: Package) -> Iterator[Hit]:
    """A data_files source is a folder, given literally or matched by a glob.

    ## What it does
    Reports literal data_files sources that are folders of the package, and globs whose
    matches include folders (`glob('config/*')` with a `config/maps/` sub-folder,
    `glob('launch/**', recursive=True)`).

    ## Why is this bad?
    setuptools installs files only: `colcon build` stops with "error: can't copy
    'config/maps': doesn't exist or not a regular file".

    ## Example
    ```python
    (os.path.join('share', package_name, 'config'), glob('config/*'))   # config/maps/ exists
    ```

    ## Use instead
    ```python
    (os.path.join('share', package_name, 'config'), glob('config/*.yaml')),
    (os.path.join('share', package_name, 'config', 'maps'), glob('config/maps/*')),
    ```
    """
    setup = checked_setup(package)
    for entry in setup.data_file_entries if setup else ():
        if entry.sources_is_text:
            continue
        for source in entry.sources:
            paths = source.matches if source.is_glob else (normalize(source.pattern) or "",)
            folders = [p for p in paths if p and not package.has_file(p) and package.has_folder(p)]
            if folders and not source.is_glob:
                yield Hit(source.span, f"`{source.pattern}` is a folder: setuptools installs "
                                       "only files")
            elif folders:
                shown = ", ".join(f"`{f.rstrip('/')}`" for f in folders[:3])
                yield Hit(source.span, f"The glob `{source.pattern}` matches the folder {shown}: "
                                       "setuptools installs only files")
