"""MAN028: a package lies inside another package's folder, where colcon never looks."""

from __future__ import annotations

import posixpath
import re
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.context import manifest_name
from pkgtool.model.files import SKIP_MARKERS, TextFile, read_text
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule

_KEPT_ASIDE = frozenset({"test", "tests", "example", "examples", "doc", "docs", "template",
                         "templates", "fixture", "fixtures", "resource", "resources", "sample",
                         "samples", "data", "thirdparty", "third_party", "3rdparty", "external",
                         "extern", "vendor", "deps"})
"""Folders whose packages are test data, examples to copy, templates or vendored libraries
(built by this package's own build, or kept as they came): kept out of colcon on purpose."""


def _named_in(folder: str, cmake: str) -> bool:
    """True when the CMake text names ``folder`` as a path of its own (``add_subdirectory(
    libs/geometry_lib)``, ``${CMAKE_CURRENT_SOURCE_DIR}/libs/geometry_lib``), not as a part
    of another word (``find_package(demo_interfaces)`` does not name ``interfaces/``)."""
    return re.search(rf"(?<![\w.-]){re.escape(folder)}(?![\w.-])", cmake) is not None


def _in_python_package(package: Package, folder: str) -> bool:
    """True when ``folder`` or a folder above it holds an ``__init__.py``."""
    parts = folder.split("/")
    return any(package.has_file("/".join(parts[:depth]) + "/__init__.py")
               for depth in range(1, len(parts) + 1))


@rule("MAN028", "nested-package", Severity.WARNING,
      fix="Move the package out of the other package's folder (beside it in the workspace's "
          "`src`), or put a `COLCON_IGNORE` file in its folder if it is kept on purpose")
def nested_package(package: Package) -> Iterator[Hit]:
    """A package.xml lies in a folder inside this package, so colcon never builds that package.

    ## What it does
    Reports each package.xml below the package's root (in no folder with a `COLCON_IGNORE`,
    `AMENT_IGNORE` or `CATKIN_IGNORE`, and in no Python package of this one), unless the
    package there has this package's name (another variant of it, kept aside), lies in a
    folder of tests, examples, documentation, templates, fixtures, resources, samples, data
    or vendored libraries (`thirdparty`, `external`, `vendor`, ...), or in a folder the
    package's CMakeLists.txt names (`add_subdirectory(lib/sophus)`: built
    with the package).

    ## Why is this bad?
    colcon (like catkin) stops looking for packages at the first folder that is one: the
    inner package is never built, installed or tested, `ros2 run` and `ros2 launch` do not
    know it, and nothing says so. A metapackage whose member packages were put in its
    folder, or a package copied into another's, is the usual cause.

    ## Example
    ```text
    src/my_robot/package.xml
    src/my_robot/my_robot_driver/package.xml   # never built
    ```

    ## Use instead
    ```text
    src/my_robot/package.xml
    src/my_robot_driver/package.xml
    ```
    """
    outer = package.name
    ignored = {path.rpartition("/")[0] for path in package.files
               if path.rpartition("/")[2] in SKIP_MARKERS}
    cmake = package.texts.get("CMakeLists.txt", "")
    for path in package.files:
        folder, _, name = path.rpartition("/")
        if name != "package.xml" or not folder or _KEPT_ASIDE & set(folder.split("/")) or \
                _in_python_package(package, folder) or _named_in(folder, cmake) or \
                any(folder == above or folder.startswith(above + "/") for above in ignored):
            continue
        read = read_text(package.root, path)
        inner = (manifest_name(read.text) if isinstance(read, TextFile) else None) or \
            posixpath.basename(folder)
        if inner != outer:
            yield Hit(Span(path, 1, 1),
                      f"`{folder}/` holds the package `{inner}`, which colcon never builds: it "
                      f"does not look for packages inside another package's folder (`{outer}`)")
