"""IFC007: a package generating interfaces is not a member of ``rosidl_interface_packages``."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.cmake_text import commands
from pkgtool.model.installed import cmake_text
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.interfaces._files import read_listing
from pkgtool.rules.registry import rule

GROUP = "rosidl_interface_packages"
"""The group rosidl wants a package installing interfaces to join."""
_SKIPPING = frozenset({"SKIP_INSTALL", "SKIP_GROUP_MEMBERSHIP_CHECK"})
"""Options of ``rosidl_generate_interfaces`` under which it does not check the group."""


@rule("IFC007", "interface-package-not-in-group", Severity.ERROR,
      fix=f"Add `<member_of_group>{GROUP}</member_of_group>` to package.xml (format 3)")
def interface_package_not_in_group(package: Package) -> Iterator[Hit]:
    """A package generating interfaces does not join the `rosidl_interface_packages` group.

    ## What it does
    Reports a package whose CMakeLists.txt (with the CMake files it includes) calls
    `rosidl_generate_interfaces` while its package.xml has no
    `<member_of_group>rosidl_interface_packages</member_of_group>`. Calls with
    `SKIP_INSTALL` or `SKIP_GROUP_MEMBERSHIP_CHECK` are left alone: rosidl checks nothing
    then; so are CMake files setting `<package>_MEMBER_OF_GROUPS` themselves (the value
    rosidl's check reads).

    ## Why is this bad?
    `rosidl_generate_interfaces` checks the group when CMake configures the package (Humble
    to Rolling) and stops with "Packages installing interfaces must include
    '<member_of_group>rosidl_interface_packages</member_of_group>' in their package.xml":
    `colcon build` fails for the package and for every package using its interfaces. The
    element exists from package.xml format 3 on.

    ## Example
    ```xml
    <package format="3">
      <name>robot_interfaces</name>
      ...
      <exec_depend>rosidl_default_runtime</exec_depend>
      <export><build_type>ament_cmake</build_type></export>
    </package>
    ```

    ## Use instead
    ```xml
    <package format="3">
      <name>robot_interfaces</name>
      ...
      <exec_depend>rosidl_default_runtime</exec_depend>
      <member_of_group>rosidl_interface_packages</member_of_group>
      <export><build_type>ament_cmake</build_type></export>
    </package>
    ```
    """
    manifest = package.manifest
    if manifest is None or manifest.is_ros1 or manifest.format is None or \
            read_listing(package) is None:
        return
    text = cmake_text(package) or ""
    calls = [args for name, args in commands(text) if name == "rosidl_generate_interfaces"]
    if not calls or any(_SKIPPING & set(args) for args in calls) or \
            "_MEMBER_OF_GROUPS" in text or \
            any(child.tag == "member_of_group" and child.text.split() == [GROUP]
                for child in manifest.root.children):
        return
    upgrade = "" if manifest.format >= 3 else \
        f" (a format {manifest.format} package.xml has no such element: make it format 3)"
    yield Hit(Span(manifest.path, manifest.root.span.line, 1),
              f"The package generates interfaces (`rosidl_generate_interfaces` in "
              f"CMakeLists.txt) but package.xml lacks `<member_of_group>{GROUP}"
              f"</member_of_group>`{upgrade}: rosidl stops `colcon build` with \"Packages "
              f"installing interfaces must include '<member_of_group>{GROUP}"
              "</member_of_group>' in their package.xml\"")
