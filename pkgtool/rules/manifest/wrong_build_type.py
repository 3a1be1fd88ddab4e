"""MAN016: a setup.py package declares another build type, or there are several."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.manifest import CMAKE_BUILD_TYPES
from pkgtool.model.package import Package
from pkgtool.model.submodules import under
from pkgtool.rules.manifest.common import build_types, tree
from pkgtool.rules.manifest.schema import token
from pkgtool.rules.registry import rule


@rule("MAN016", "wrong-build-type", Severity.ERROR,
      fix="Write `<build_type>ament_python</build_type>` for a setup.py package")
def wrong_build_type(package: Package) -> Iterator[Hit]:
    """A package declares a build type its build files do not fit, or several.

    ## What it does
    Reports a build type other than ``ament_python`` in a package that has setup.py and no
    CMakeLists.txt, ``ament_cmake`` or ``cmake`` in a package without CMakeLists.txt, and
    more than one unconditional ``<build_type>``. Build types with a
    ``condition`` are not judged. The reverse, ``ament_python`` without setup.py, is SET001
    (missing setup.py), so that one defect gives one finding.

    ## Why is this bad?
    colcon picks the build tool from ``<build_type>`` alone: ``ament_cmake`` on a setup.py
    package, or on any package without CMakeLists.txt, fails for want of it, a misspelt type
    is not built at all ("No task extension to 'build'"), and with two build types colcon
    warns and builds the package as a plain Python package, without the ament index entry
    ``ros2 run`` needs.

    ## Example
    ```xml
    <export>
      <build_type>ament_cmake</build_type>
    </export>
    ```

    ## Use instead
    ```xml
    <export>
      <build_type>ament_python</build_type>
    </export>
    ```
    """
    found = tree(package)
    if found is None:
        return
    elements = build_types(found)
    if not elements or any(e.attribute("condition") is not None for e in elements):
        return
    for extra in elements[1:]:
        yield Hit(extra.span, f"Second `<build_type>` (first on line {elements[0].span.line})",
                  "Keep one `<build_type>`")
    element, kind = elements[0], token(elements[0].text)
    if kind != "ament_python" and package.has_file("setup.py") and \
            not package.has_file("CMakeLists.txt"):
        declared = f"Build type `{kind}`" if kind else "Empty `<build_type>`"
        yield Hit(element.span, f"{declared} but the package has setup.py and no CMakeLists.txt")
    elif kind in CMAKE_BUILD_TYPES and not package.has_file("CMakeLists.txt") and \
            not under("CMakeLists.txt", package.unfetched):
        yield Hit(element.span, f"Build type `{kind}` but the package has no CMakeLists.txt: "
                  "colcon build stops (\"The source directory does not appear to contain "
                  "CMakeLists.txt\")", "Add the package's CMakeLists.txt (or the build type of "
                  "what the package is)")
