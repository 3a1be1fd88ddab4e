"""IFC006: an interface file that ``rosidl_generate_interfaces`` does not list."""

from __future__ import annotations

import posixpath
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.interfaces._files import read_listing
from pkgtool.rules.registry import rule

_KIND_NAMES = {"msg": "message", "srv": "service", "action": "action"}


@rule("IFC006", "unlisted-interface-file", Severity.WARNING,
      fix="Add the file to `rosidl_generate_interfaces`, or delete it")
def unlisted_interface_file(package: Package) -> Iterator[Hit]:
    """An interface file of the package that `rosidl_generate_interfaces` does not list.

    ## What it does
    Reads the interface files the package's CMakeLists.txt (with the CMake files it includes)
    passes to `rosidl_generate_interfaces` (literally, through variables it sets, or through
    `file(GLOB ...)`) and reports each `.msg`, `.srv` and `.action` file of the package's
    top-level `msg/`, `srv/` and `action/` folders that the list leaves out. A list that
    takes files from another package's variables, and CMake code that rebuilds lists
    (`foreach`, `list(APPEND ...)`), are left alone.

    ## Why is this bad?
    rosidl generates only what it is given: the file builds nothing, and code importing the
    interface (`from my_interfaces.srv import Reset`) fails with ImportError, although the
    definition sits right there in the package. It is usually a file added after the
    CMakeLists.txt was written.

    ## Example
    ```cmake
    rosidl_generate_interfaces(${PROJECT_NAME} "msg/Status.msg")
    # the package also has srv/Reset.srv
    ```

    ## Use instead
    ```cmake
    rosidl_generate_interfaces(${PROJECT_NAME} "msg/Status.msg" "srv/Reset.srv")
    ```
    """
    listed = read_listing(package)
    if listed is None or listed.open or not listed.files:
        return
    for path in package.files:
        folder, name = posixpath.split(path)
        stem, _, suffix = name.rpartition(".")
        if folder in _KIND_NAMES and suffix == folder and path not in listed.files:
            yield Hit(Span(path, 1, 1), f"`{path}` is not listed in "
                      "`rosidl_generate_interfaces`: no `" + stem + f"` {_KIND_NAMES[folder]} "
                      "is generated, and importing it raises ImportError")
