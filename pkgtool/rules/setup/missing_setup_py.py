"""SET001: an ament_python package without setup.py."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.registry import rule


@rule("SET001", "missing-setup-py", Severity.ERROR,
      fix="Add a `setup.py` that calls `setup()`, as `ros2 pkg create --build-type "
          "ament_python` writes it")
def missing_setup_py(package: Package) -> Iterator[Hit]:
    """A package that colcon builds with setup.py has none.

    ## What it does
    Reports a package.xml whose `<build_type>` is `ament_python`, or that declares no build
    type, has no CMakeLists.txt and holds Python modules (launch files aside), when there is
    no setup.py next to it; not one depending on `catkin` as its build tool, which colcon
    builds as a catkin package (MAN015 says what it lacks).

    ## Why is this bad?
    colcon's ament_python build runs setup.py; without it the package does not build, and
    nothing (modules, console scripts, the ament index marker) is installed.

    ## Example
    ```text
    my_pkg/
      package.xml        <build_type>ament_python</build_type>
      my_pkg/node.py
    ```

    ## Use instead
    ```text
    my_pkg/
      package.xml
      setup.py           setup(name='my_pkg', packages=['my_pkg'], ...)
      setup.cfg
      resource/my_pkg
      my_pkg/__init__.py
      my_pkg/node.py
    ```
    """
    manifest = package.manifest
    if manifest is None or package.has_file("setup.py"):
        return
    if manifest.build_type is not None:
        if manifest.build_type.value == "ament_python":
            cmake = package.has_file("CMakeLists.txt")
            yield Hit(manifest.build_type.span,
                      "`package.xml` declares `ament_python`, but there is no `setup.py`"
                      + (" (there is a `CMakeLists.txt`)" if cmake else ""),
                      "Declare `<build_type>ament_cmake</build_type>` if CMake builds this "
                      "package; otherwise add a `setup.py`" if cmake else None)
        return
    launch = {f.path for f in package.launch_files}
    has_python = any(not m.is_test and m.path not in launch for m in package.modules)
    if has_python and not package.has_file("CMakeLists.txt") and \
            "catkin" not in manifest.depends({"buildtool_depend"}):
        yield Hit(manifest.root.span,
                  "The package holds Python modules but has neither `setup.py` nor "
                  "`CMakeLists.txt`")
