"""DAT016: data_files installs into the folder of a Python version the distribution lacks."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rosdistro import PYTHON_VERSIONS
from pkgtool.model.package import Package
from pkgtool.rules.registry import rule
from pkgtool.lazy_regex import lazy_pattern

_VERSIONED = lazy_pattern(r"(?:^|/)python(\d+\.\d+)(?:/|$)")
"""A destination folder named for one Python version (``lib/python3.8/site-packages``)."""


@rule("DAT016", "python-version-in-data-files", Severity.ERROR,
      fix="Install the files into `share/<package>` and find them with "
          "`get_package_share_directory('<package>')`")
def python_version_in_data_files(package: Package) -> Iterator[Hit]:
    """data_files installs into a folder named for a Python version the target distribution
    does not run.

    ## What it does
    Reports a data_files destination with a `pythonX.Y` folder in it
    (`lib/python3.8/site-packages/my_pkg`) whose version is not the Python of the target
    distribution (3.10 for Humble, 3.12 for Jazzy, Kilted and Rolling).

    ## Why is this bad?
    The files land in a folder that no interpreter of the distribution reads: the package's
    modules are installed into the running Python's `site-packages`, so code looking for the
    files next to itself (or on `sys.path`) fails with FileNotFoundError or ImportError. The
    version was usually copied from an older distribution (Foxy's 3.8).

    ## Example
    ```python
    data_files=[('lib/python3.8/site-packages/my_pkg', ['my_pkg/model.onnx'])]
    ```

    ## Use instead
    ```python
    data_files=[('share/my_pkg', ['my_pkg/model.onnx'])]
    ```
    """
    setup = package.setup_py
    wanted = PYTHON_VERSIONS.get(package.context.distro)
    if setup is None or wanted is None:
        return
    for entry in setup.data_files or ():
        found = _VERSIONED.search(entry.destination)
        if found is not None and found.group(1) != wanted:
            yield Hit(entry.span, f"data_files installs into `{entry.destination}`, a folder of "
                      f"Python {found.group(1)}: ROS 2 {package.context.distro} runs Python "
                      f"{wanted}, which never looks there")
