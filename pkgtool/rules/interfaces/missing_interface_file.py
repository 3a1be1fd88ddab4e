"""IFC005: ``rosidl_generate_interfaces`` lists an interface file the package does not have."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.model.submodules import ignored, under
from pkgtool.rules.interfaces._files import read_listing
from pkgtool.rules.registry import rule


@rule("IFC005", "missing-interface-file", Severity.ERROR,
      fix="Write the interface file, or take it out of `rosidl_generate_interfaces`")
def missing_interface_file(package: Package) -> Iterator[Hit]:
    """The CMakeLists.txt passes `rosidl_generate_interfaces` a file the package lacks.

    ## What it does
    Reads the interface files the package's CMakeLists.txt (with the CMake files it
    includes) lists in `rosidl_generate_interfaces` (literally, or through variables it
    sets) and reports those that are no file of the package: a misspelt name, a file never
    committed, a folder renamed. Files of a git submodule that is not checked out, files a
    `.gitignore` leaves out (generated before the build), names without a folder, and the
    lists of a CMakeLists.txt that rebuilds them (`foreach`, `list(APPEND ...)`) are left
    alone.

    ## Why is this bad?
    The build stops: rosidl cannot read the file, so `colcon build` fails for the package
    and every package depending on it, and no interface of it (not even those whose files
    exist) is generated.

    ## Example
    ```cmake
    rosidl_generate_interfaces(${PROJECT_NAME} "msg/Status.msg" "srv/Waypoints.srv")
    # the package has msg/Status.msg only
    ```

    ## Use instead
    ```cmake
    rosidl_generate_interfaces(${PROJECT_NAME} "msg/Status.msg")
    ```
    """
    listed = read_listing(package)
    if listed is None:
        return
    cmake = package.texts.get("CMakeLists.txt", "")
    for path in sorted(listed.files):
        if "/" not in path or package.has_file(path) or under(path, package.unfetched) or \
                ignored(path, package.ignores):
            continue
        at = cmake.find(path)
        line = cmake.count("\n", 0, at) + 1 if at >= 0 else 1
        yield Hit(Span("CMakeLists.txt", line, 1),
                  f"`rosidl_generate_interfaces` lists `{path}`, which the package does not "
                  "have: the build stops there and no interface of the package is generated")
