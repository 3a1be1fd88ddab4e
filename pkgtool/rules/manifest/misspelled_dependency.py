"""MAN021: a dependency key that resolves to nothing but is spelled like one that does."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.imports import declaration_cause
from pkgtool.rules.dependency_names import unknown_dependencies
from pkgtool.rules.registry import rule


@rule("MAN021", "misspelled-dependency", Severity.ERROR,
      fix="Write the name of the ROS package or rosdep key you meant")
def misspelled_dependency(package: Package) -> Iterator[Hit]:
    """A ``*_depend`` names nothing rosdep knows, and a known name is spelled almost the same.

    ## What it does
    Checks every dependency key of package.xml against the ROS packages released for the
    target distribution (``--rosdistro``, or ``rosdistro`` in ``[tool.pkgtool]``; default
    jazzy), the rosdep keys of rosdep's ``base.yaml`` and ``python.yaml``, and the packages
    of the same workspace (those linted in the same run, and every package under the ``src``
    folder of the colcon workspace the package is in). A key that is none of these but is
    spelled like one of them is reported with that name (or spelled like a module the code
    imports that no declared key provides: `simpole_pid` for `import simple_pid` is
    `python3-simple-pid-pip`), unless the package uses exactly that
    name (a Python import of it, a ``find_package()`` of it in CMakeLists.txt, a launch file
    starting its nodes, a URDF, xacro, SDF or RViz file naming it in ``$(find name)`` or
    ``package://name/``) or already declares the near name for the same use: a package
    built from source elsewhere, which MAN022 reports as unknown. Dependencies whose REP 149
    ``condition`` is false for the target (``$ROS_VERSION == 1``) are skipped, and so are
    ROS 1 (catkin) manifests. Names with no near miss are MAN022's. When the misspelt key is
    a run dependency, the imports (DEP001) and launch files (LCH002) left without the name it
    suggests are the same mistake: they are listed in this finding, not reported apart.

    ## Why is this bad?
    ``rosdep install`` stops with "Cannot locate rosdep definition", the build farm rejects
    the release, and colcon orders the build without the intended dependency.

    ## Example
    ```xml
    <exec_depend>sensor_msg</exec_depend>
    ```

    ## Use instead
    ```xml
    <exec_depend>sensor_msgs</exec_depend>
    ```
    """
    for unknown in unknown_dependencies(package):
        if unknown.close:
            tag = unknown.dependency.tag
            whose = f", the key of `{unknown.module}`, which the code imports" \
                if unknown.module else ""
            yield Hit(unknown.dependency.span,
                      f"{unknown.describe(package.context.distro)}; did you mean "
                      f"`{unknown.close}`{whose}?", f"Write `<{tag}>{unknown.close}</{tag}>`",
                      cause=declaration_cause(tag, unknown.close))
