"""MAN022: a dependency key that is no released ROS package, rosdep key or workspace package."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.dependency_names import unknown_dependencies
from pkgtool.rules.registry import rule


@rule("MAN022", "unknown-dependency", Severity.WARNING,
      fix="Check the key with `rosdep resolve`, or add the package to the workspace")
def unknown_dependency(package: Package) -> Iterator[Hit]:
    """A ``*_depend`` names nothing that rosdep or the workspace provides for the target.

    ## What it does
    Like MAN021 (the same sources and exceptions), for keys that are not spelled like any
    known name: a package from a private repository or another workspace, a key of a custom
    rosdep source, a package that the target distribution does not release (the message
    names the distributions that do), or a made-up name. A name of a git submodule of the
    repository that is not checked out is left alone (it holds the package once fetched).
    It is a warning because private rosdep sources and overlay workspaces are legitimate.

    ## Why is this bad?
    On a machine with only the public rosdep sources, ``rosdep install`` cannot install the
    dependency, so building or running the package fails there.

    ## Example
    ```xml
    <exec_depend>ros1_bridge</exec_depend>  <!-- jazzy target: not released for jazzy -->
    ```

    ## Use instead
    Depend on what the target distribution has, build the package from source in the same
    workspace, or add a rosdep source that defines the key (`rosdep resolve KEY` tells).
    """
    for unknown in unknown_dependencies(package):
        if not unknown.close:
            yield Hit(unknown.dependency.span, unknown.describe(package.context.distro))
