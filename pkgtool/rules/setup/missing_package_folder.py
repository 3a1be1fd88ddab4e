"""SET011: packages= names a package whose folder does not exist."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.submodules import under
from pkgtool.rules.registry import rule
from pkgtool.rules.setup_values import listed_packages


@rule("SET011", "missing-package-folder", Severity.ERROR,
      fix="List the folder that holds the Python package (with `__init__.py`), or rename it")
def missing_package_folder(package: Package) -> Iterator[Hit]:
    """`packages=[...]` lists a package whose folder does not exist.

    ## What it does
    For an explicit `packages` list, maps each name to its folder the way setuptools does
    (respecting `package_dir`) and reports names whose folder holds no files.

    ## Why is this bad?
    The build stops with "error: package directory 'x' does not exist". It typically happens
    when the Python package folder is renamed, or `package_name` (the ROS name) is used for a
    folder called differently.

    ## Example
    ```python
    package_name = 'robot_monitor'
    setup(name=package_name, packages=[package_name])   # the code is in monitor/
    ```

    ## Use instead
    ```python
    setup(name=package_name, packages=['monitor'])
    ```
    """
    folders = {f.rsplit("/", 1)[0] for f in package.files if "/" in f}
    for name, folder, span in listed_packages(package):
        if folder and not any(f == folder or f.startswith(folder + "/") for f in folders) \
                and not under(folder, package.unfetched):
            yield Hit(span, f"`packages` lists `{name}`, but there is no folder `{folder}`")
