"""MAN015: no ``<export><build_type>``, in a package without CMakeLists.txt."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.manifest.common import build_types, tree
from pkgtool.rules.registry import rule


@rule("MAN015", "missing-build-type", Severity.ERROR,
      fix="Add `<export><build_type>ament_python</build_type></export>` at the end of "
          "`<package>`")
def missing_build_type(package: Package) -> Iterator[Hit]:
    """package.xml declares no build type, and the package has no CMakeLists.txt.

    ## What it does
    Reports a manifest without ``<build_type>`` in ``<export>`` when the package has no
    CMakeLists.txt. (With a CMakeLists.txt it may be a catkin package, which needs none.) A
    ROS 1 package (catkin its build tool) without CMakeLists.txt is told that it needs one,
    not a build type.

    ## Why is this bad?
    Without a build type catkin_pkg answers ``catkin``, so colcon identifies the package as
    ``ros.catkin`` and runs CMake on it, which fails: "does not appear to contain
    CMakeLists.txt". ``ros2 pkg create --build-type ament_python`` always writes the element.

    ## Example
    ```xml
      <test_depend>python3-pytest</test_depend>
    </package>
    ```

    ## Use instead
    ```xml
      <test_depend>python3-pytest</test_depend>
      <export>
        <build_type>ament_python</build_type>
      </export>
    </package>
    ```
    """
    found = tree(package)
    if found is None or build_types(found) or package.has_file("CMakeLists.txt"):
        return
    exports = list(found.named("export"))
    where = exports[0].span if exports else found.root.span
    if package.manifest is not None and package.manifest.is_ros1:
        yield Hit(where, "This catkin package has no CMakeLists.txt: catkin (and colcon, which "
                  "builds it as `catkin`) runs CMake on it and fails",
                  "Add the CMakeLists.txt catkin builds it with (`catkin_package()`, and "
                  "`catkin_python_setup()` for its setup.py)")
        return
    kind = "a Python" if package.has_file("setup.py") else "this"
    yield Hit(where, f"No `<build_type>` in `<export>`: colcon would build {kind} package with "
              "CMake, as `catkin`, and fail")
