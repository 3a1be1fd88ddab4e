"""DEP012: an installed robot description, world or RViz file names a package that package.xml
does not declare, or that no package has as its name."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.lazy_regex import lazy_pattern
from pkgtool.model.description_files import PackageMention, package_mentions
from pkgtool.model.installed import cmake_installed, cmake_text, installed_data, is_ament_python
from pkgtool.model.package import Package
from pkgtool.model.submodules import under
from pkgtool.rules.imports import RUNTIME, declared
from pkgtool.rules.package_lookups import unlisted_packages
from pkgtool.rules.registry import rule
from pkgtool.rules.ros1_platform import is_ros1_package


_FILTERED = lazy_pattern(r"\b(?:FILES_MATCHING|PATTERN|REGEX)\b")
"""Options of a CMake ``install(DIRECTORY ...)`` that leave some of the folder's files out."""


@rule("DEP012", "undeclared-description-package", Severity.WARNING,
      fix="Add an `<exec_depend>` for the package to package.xml, or fix its name")
def undeclared_description_package(package: Package) -> Iterator[Hit]:
    """An installed robot description, world or RViz file names an undeclared package.

    ## What it does
    Reads the URDF, xacro, SDF, SRDF, `.world` and `.rviz` files the package installs
    (through `data_files`, or an `install()` of its CMakeLists.txt) for the packages they
    name: `$(find other)` and `$(find-pkg-share other)` (xacro includes and file paths) and
    `package://other/...` URIs (meshes, textures). Each name other than this package's must be
    an `<exec_depend>` or `<depend>`, or be brought in by a declared metapackage; a name that no
    package of the target's release nor of the packages linted with it has is said so, with
    the package it is a typo of, if any (a description exported or copied under another
    package's name). Comments name nothing (XML's, and `#` lines of RViz's YAML), nor xacro's
    escaped `$$(find x)`. Each package is reported once, at the first file naming it.
    Packages of the workspace are left alone: a description naming its
    bringup package's controller settings (`$(find robot_bringup)/config/controllers.yaml`)
    is used by that package's launch files, which must declare the description, and
    declaring both would make a cycle colcon cannot order. Files the package does not install,
    and packages whose installed files pkgtool cannot tell (a CMake `install()` that filters
    with `PATTERN`, `REGEX` or `FILES_MATCHING`), are not read.

    ## Why is this bad?
    The description is used on a machine set up with rosdep, which installs only what
    package.xml declares: xacro stops at `$(find other)` ("package not found"), and
    robot_state_publisher's users (RViz, Gazebo) cannot load the meshes `package://other/`
    points at. A name no package has fails everywhere.

    ## Example
    ```xml
    <!-- in my_robot_description, which declares no dependency on ur_description -->
    <xacro:include filename="$(find ur_description)/urdf/ur_macro.xacro"/>
    ```

    ## Use instead
    ```xml
    <exec_depend>ur_description</exec_depend>
    ```
    """
    if package.manifest is None or is_ros1_package(package):
        return
    installed = _installed_description_files(package)
    if not installed:
        return
    available = declared(package, RUNTIME)
    workspace = package.context.workspace
    mentions = [m for m in package_mentions(package) if m.span.path in installed and
                (m.package == package.name or m.package not in workspace)]
    files: dict[str, list[PackageMention]] = {}
    for mention in mentions:  # in file order: the first file naming a package stands for all
        files.setdefault(mention.package, []).append(mention)
    for name, named in files.items():
        first, others = named[0].span.path, {m.span.path for m in named} - {named[0].span.path}
        user = f"the installed file `{first}`" + (
            f" (and {len(others)} more)" if others else "")
        yield from unlisted_packages(package, [(name, named[0].span)], available, user)


def _installed_description_files(package: Package) -> frozenset[str]:
    """The package's description files colcon installs: the sources of its data_files, or what
    its CMakeLists.txt installs; none when that is not known."""
    paths = {mention.span.path for mention in package_mentions(package)}
    if not paths:
        return frozenset()
    if is_ament_python(package):
        return frozenset(paths & set((installed_data(package) or {}).values()))
    sources = cmake_installed(package)
    if sources is None or _FILTERED.search(cmake_text(package) or ""):
        return frozenset()
    return frozenset(path for path in paths if "." in sources or under(path, sources))
