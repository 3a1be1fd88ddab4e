"""MAN020: a ROS 2 Python package (by its setup.py) that has no package.xml."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.plain_projects import ros_package_entry
from pkgtool.rules.registry import rule


@rule("MAN020", "missing-package-xml", Severity.ERROR,
      fix="Add a format 3 `package.xml` with the package's name, version, description, "
          "maintainer, license, dependencies and `<build_type>ament_python</build_type>`")
def missing_package_xml(package: Package) -> Iterator[Hit]:
    """A ROS 2 Python package has a setup.py but no package.xml.

    ## What it does
    Reports a package folder without `package.xml` whose setup.py installs `package.xml` or
    the ament index marker through `data_files`, which only ROS packages do. Plain Python
    projects (setup.py alone) are not reported.

    ## Why is this bad?
    Without package.xml colcon builds the folder as a plain Python package: no ament index
    entry, no dependencies for rosdep, and `ros2 run`/`ros2 launch` report "package not
    found". The `data_files` line installing package.xml fails the build outright.

    ## Example
    ```text
    my_pkg/setup.py   data_files=[..., ('share/' + package_name, ['package.xml'])]
    (no my_pkg/package.xml)
    ```

    ## Use instead
    Restore `package.xml` next to setup.py (`ros2 pkg create` or `pkgtool create` writes one).
    """
    setup = package.setup_py
    if setup is None or package.has_file("package.xml") or setup.setup_span is None:
        return
    entry = ros_package_entry(package)
    if entry is not None:
        yield Hit(entry.span, "The package has no `package.xml`, but setup.py installs "
                              "ROS package files: colcon will not build it as a ROS package")
