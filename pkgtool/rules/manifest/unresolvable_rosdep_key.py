"""MAN023: a rosdep key with no definition for the target distribution's Ubuntu release."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge import rosdistro
from pkgtool.model.package import Package
from pkgtool.rules.dependency_names import checked_dependencies, is_local
from pkgtool.rules.registry import rule


@rule("MAN023", "unresolvable-rosdep-key", Severity.WARNING,
      fix="Use a key that resolves on the target (a `-pip` key, or the Python 3 key)")
def unresolvable_rosdep_key(package: Package) -> Iterator[Hit]:
    """A rosdep key is known but installs nothing on the target distribution's Ubuntu release.

    ## What it does
    Reports dependency keys that are rosdep keys (and not ROS packages of the target
    distribution or workspace packages) whose definition has no entry for the Ubuntu release
    of the target distribution (jammy for humble, noble for jazzy and kilted, the release
    rolling targets): Python 2 keys such as ``python-numpy`` and keys marked ``null`` there.
    When another key installs the same Python module there, it is named.

    ## Why is this bad?
    ``rosdep install`` fails with "No definition of [key] for OS version", so nothing
    installs the dependency on the robot or on the build farm.

    ## Example
    ```xml
    <exec_depend>python3-open3d</exec_depend>  <!-- null for Ubuntu noble -->
    ```

    ## Use instead
    ```xml
    <exec_depend>python3-open3d-pip</exec_depend>
    ```
    """
    distro = package.context.distro
    for dependency in checked_dependencies(package):
        key = dependency.name
        if (is_local(package, key) or rosdistro.is_released_package(key, distro)
                or not rosdistro.is_rosdep_key(key) or rosdistro.key_resolves(key, distro)):
            continue
        other = rosdistro.alternative_key(key, distro)
        instead = f"; `{other}` installs the same module there" if other else ""
        yield Hit(dependency.span, f"rosdep key `{key}` has no definition for {distro}'s "
                  f"Ubuntu release{instead}",
                  f"Write `<{dependency.tag}>{other}</{dependency.tag}>`" if other else None)
