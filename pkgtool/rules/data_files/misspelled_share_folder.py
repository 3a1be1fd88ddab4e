"""DAT021: data_files installs into ``share/<name>`` where the name is a typo of the package's."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rosdistro import digits_differ, is_typo
from pkgtool.model.package import Package
from pkgtool.rules.data_files.common import destination_parts
from pkgtool.rules.registry import rule
from pkgtool.rules.setup_values import checked_setup


@rule("DAT021", "misspelled-share-folder", Severity.ERROR,
      fix="Install into `share/<package>`: `os.path.join('share', package_name, ...)`")
def misspelled_share_folder(package: Package) -> Iterator[Hit]:
    """data_files installs into the share folder of a name a typo away from the package's.

    ## What it does
    Reports a data_files destination `share/<name>/...` whose `<name>` is not the package's
    name but a typo of it (one edit, two for long names; names differing in a digit are
    never a typo): `('share/my_robto/config', ...)` in the package `my_robot`. Destinations
    built from `package_name` and other packages' share folders (`share/ament_index/...`,
    `share/other_package`) are not reported, nor the name setup.py gives the package: when
    that one is misspelt, SET003 reports it with the places that follow it.

    ## Why is this bad?
    The files land in `install/<package>/share/my_robto`, a folder no package owns:
    `get_package_share_directory('my_robot')` and `FindPackageShare('my_robot')` lead to
    `share/my_robot`, where they are not, so whatever reads them fails once installed (a
    parameter file is silently not loaded), while the source tree looked fine.

    ## Example
    ```python
    data_files=[('share/my_robto/config', glob('config/*.yaml'))]
    ```

    ## Use instead
    ```python
    data_files=[(os.path.join('share', package_name, 'config'), glob('config/*.yaml'))]
    ```
    """
    setup = checked_setup(package)
    name = package.name
    own = setup.name.value if setup and setup.name else None
    for entry in setup.data_file_entries if setup else ():
        parts = destination_parts(entry)
        if len(parts) < 2 or parts[0] != "share" or parts[1] in (name, own) or \
                not is_typo(parts[1], name) or digits_differ(parts[1], name):
            continue
        rest = "/".join(parts[2:])
        meant = f"share/{name}" + (f"/{rest}" if rest else "")
        yield Hit(entry.span, f"data_files installs into `{entry.destination}`: `{parts[1]}` "
                  f"is a typo of the package's name `{name}`, and "
                  f"`get_package_share_directory('{name}')` leads to `share/{name}`, where the "
                  "files are not", f"Install into `{meant}`")
