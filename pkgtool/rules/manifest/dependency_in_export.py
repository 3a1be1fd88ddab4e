"""MAN024: a dependency tag written inside ``<export>``, where no tool reads it."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.imports import declaration_cause
from pkgtool.rules.manifest.common import snippet, tree
from pkgtool.rules.manifest.schema import DEPENDS_1, DEPENDS_2, GROUP_TAGS, token
from pkgtool.rules.package_lookups import known_package
from pkgtool.rules.registry import rule

_DEPENDENCY_TAGS = frozenset({*DEPENDS_1, *DEPENDS_2, *GROUP_TAGS})
"""The dependency tags of every format (``conflict``, ``replace`` and the group tags too)."""
_COVERED = frozenset({"build_depend", "build_export_depend", "exec_depend"})
"""The tags a ``<depend>`` of the same key stands for."""


@rule("MAN024", "dependency-in-export", Severity.ERROR,
      fix="Move it out of `<export>`, next to the other dependencies of `<package>`")
def dependency_in_export(package: Package) -> Iterator[Hit]:
    """A dependency is written inside ``<export>``, where it declares nothing.

    ## What it does
    Reports the children of ``<export>`` that are dependency tags of a package.xml format:
    ``<depend>``, ``<exec_depend>``, ``<build_depend>``, ``<test_depend>``, the other
    ``*_depend`` tags, ``<conflict>``, ``<replace>``, ``<group_depend>`` and
    ``<member_of_group>``. Deeper elements (the content of a tool's own export element) are
    left alone, and so are copies of what `<package>` declares itself (the same tag and key,
    or a `<depend>` of the key for a build, export or exec dependency, or a `<depend>` of a
    key `<package>` declares for build and exec): inert; so are tags naming no package of
    the workspace or the release nor a rosdep key (the package's own module: moved out of
    `<export>`, rosdep could not resolve it).

    ## Why is this bad?
    The schema lets ``<export>`` hold anything, so nothing complains, but catkin_pkg, colcon,
    rosdep and bloom read dependencies only from the children of ``<package>``: one inside
    ``<export>`` is an opaque export entry. rosdep does not install it, colcon does not build
    the package after it and the released package does not depend on it, so the import it
    was meant for fails on a fresh machine.

    ## Example
    ```xml
    <export>
      <build_type>ament_python</build_type>
      <exec_depend>std_msgs</exec_depend>
    </export>
    ```

    ## Use instead
    ```xml
    <exec_depend>std_msgs</exec_depend>
    <export>
      <build_type>ament_python</build_type>
    </export>
    ```
    """
    found = tree(package)
    if found is None:
        return
    declared = {(child.tag, token(child.text)) for child in found.root.children}
    for export in found.named("export"):
        for child in export.children:
            key = token(child.text)
            if child.tag in _DEPENDENCY_TAGS and (child.tag, key) not in declared and \
                    (child.tag in GROUP_TAGS or  # a group's name: no package's
                     all(known_package(package, name) for name in key.split())) and \
                    not (child.tag in _COVERED and ("depend", key) in declared) and \
                    not (child.tag == "depend" and {("build_depend", key),
                                                    ("exec_depend", key)} <= declared):
                yield Hit(child.span, f"`{snippet(child)}` is inside `<export>`: no build or "
                                      "install tool reads it there, so it declares nothing",
                          cause=declaration_cause(child.tag, key))
