"""DAT019: data_files installs into a folder of the install prefix that nothing searches."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.registry import rule
from pkgtool.rules.setup_values import checked_setup

PREFIX_FOLDERS = frozenset({"share", "lib", "lib64", "libexec", "bin", "sbin", "include", "etc",
                            "opt", "var"})
"""The folders of an install prefix that colcon, ament and the system look in."""


@rule("DAT019", "misplaced-data-files", Severity.ERROR,
      fix="Install the files under `share/<package>` (`os.path.join('share', package_name, "
          "...)`) and find them with `get_package_share_directory('<package>')`")
def misplaced_data_files(package: Package) -> Iterator[Hit]:
    """data_files installs into a folder of the install prefix that nothing searches.

    ## What it does
    Reports a relative data_files destination whose first folder is none of the install
    prefix's (`share`, `lib`, `bin`, `include`, `etc`, ...): `('config', glob('config/*'))`
    or `(os.path.join('limo', 'config'), ...)`, a destination that forgot its `share/<package>`
    part. Absolute destinations (`/etc/udev/rules.d`) install outside the prefix on purpose
    and are left alone, as are destinations that are not known statically.

    ## Why is this bad?
    setuptools installs the files into `<prefix>/config` (`install/<package>/config`), beside
    `share` and `lib`:
    `get_package_share_directory` leads to `share/<package>`, where they are not, so the
    launch file or node reading them fails with FileNotFoundError (or a parameter file is
    silently not loaded) once installed, while the source tree looked fine.

    ## Example
    ```python
    data_files=[('config', glob('config/*.yaml'))]
    ```

    ## Use instead
    ```python
    data_files=[(os.path.join('share', package_name, 'config'), glob('config/*.yaml'))]
    ```
    """
    setup = checked_setup(package)
    for entry in setup.data_file_entries if setup else ():
        first = entry.destination.replace("\\", "/").lstrip("./").split("/")[0]
        if entry.destination.startswith(("/", "~", "$")) or not first or \
                first in PREFIX_FOLDERS or not entry.sources:
            continue
        yield Hit(entry.span, f"data_files installs into `<prefix>/{entry.destination}`, "
                  f"beside `share` and `lib`: `get_package_share_directory('{package.name}')` "
                  "leads to `share/` instead, and nothing finds the files there")
