"""SET014: find_packages() installs a launch, test or data folder as a top-level package."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.installed import DATA_FOLDERS, found_top_level
from pkgtool.model.package import Package
from pkgtool.rules.imports import all_python, provided_elsewhere
from pkgtool.rules.registry import rule
from pkgtool.rules.setup_values import checked_setup


def _imported_as_code(package: Package, name: str) -> bool:
    """True when a Python file outside the folder imports it: the folder is meant as code."""
    return any(imported.top_level == name for module in all_python(package)
               if not module.path.startswith(name + "/") for imported in module.imports)


@rule("SET014", "data-folder-installed-as-package", Severity.WARNING,
      fix="Exclude it, e.g. `find_packages(exclude=['test', 'launch'])`, or remove its "
          "`__init__.py`")
def data_folder_installed_as_package(package: Package) -> Iterator[Hit]:
    """`find_packages()` installs a launch, test or data folder as a top-level Python package.

    ## What it does
    Looks at the top-level packages `find_packages()` (folders with `__init__.py`) or
    `find_namespace_packages()` (every folder) install, and reports those named like a ROS
    package's data folders: `launch`, `test`, `tests`, `config`, `resource`, `models`,
    `urdf`, `worlds`, `maps`, `rviz`, `msg`, ... A folder named like a module nothing else
    provides (`config`) is left alone when the package's code imports it (it is code then);
    one named like a module of the standard library, ROS or rosdep (`launch`, `test`) is
    always reported, and the import rules never take it for the package's own module. A
    folder without `__init__.py` (`find_namespace_packages()`) becomes a namespace package,
    which hides no regular package of that name (Python prefers those): it is reported as
    installed, not as hiding.

    ## Why is this bad?
    The folder lands in `site-packages` as a package of that name. An installed `launch`
    package comes first on `PYTHONPATH` once the workspace is sourced and hides ROS 2's own
    `launch`, so `ros2 launch` fails for every package; two packages installing `config` or
    `test` overwrite each other.

    ## Example
    ```python
    setup(name=package_name, packages=find_packages())   # launch/__init__.py exists
    ```

    ## Use instead
    ```python
    setup(name=package_name, packages=find_packages(exclude=['test', 'launch']))
    ```
    """
    setup = checked_setup(package)
    if setup is None or setup.packages is None:
        return
    finder = f"{setup.packages.kind}()"
    where = "" if setup.packages.where in (".", "") else setup.packages.where.strip("/") + "/"
    for name in sorted(found_top_level(package) & DATA_FOLDERS - {package.name}):
        if provided_elsewhere(name, package.context) and \
                package.has_file(f"{where}{name}/__init__.py"):
            yield Hit(setup.packages.span, f"`{finder}` installs the folder `{name}` as the "
                      f"top-level package `{name}`, which hides the real `{name}` module")
        elif not _imported_as_code(package, name):
            yield Hit(setup.packages.span, f"`{finder}` installs the folder `{name}` as the "
                      f"top-level package `{name}`")
