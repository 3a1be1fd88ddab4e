"""DEP006: a declared run-time dependency that nothing in the package imports or launches."""

from __future__ import annotations

import re
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.ros_names import looks_like_ros
from pkgtool.knowledge.rosdep import (ALTERNATIVE_KEYS, ROS_MODULE_PACKAGES, STDLIB_NAMED_KEYS,
                                      brought_in)
from pkgtool.knowledge.rosdistro import modules_of_key
from pkgtool.model.package import Package
from pkgtool.rules.dependency_names import launched_packages
from pkgtool.rules.imports import RUNTIME, all_python, declared, misspelt_package, needs
from pkgtool.rules.registry import rule

NEVER_IMPORTED = frozenset({
    "ros2launch", "launch", "launch_ros", "launch_xml", "launch_yaml", "launch_testing",
    "launch_testing_ros", "launch_testing_ament_cmake", "rosidl_default_runtime",
    "rosidl_default_generators", "python3-pytest", "python3-setuptools", "rclpy_components",
})
"""Keys packages declare for tools and runtimes, not for imports."""
_CONFIG_SUFFIXES = (".yaml", ".yml", ".json", ".urdf", ".xacro", ".sdf", ".world", ".rviz",
                    ".xml", ".msg", ".srv", ".action", ".idl")


def _import_names(key: str) -> set[str]:
    names = {key}
    names.update(modules_of_key(key))
    names.update(m for m, k in ROS_MODULE_PACKAGES.items() if k == key)
    names.update(m for m, keys in ALTERNATIVE_KEYS.items() if key in keys)
    return names


def _import_only(key: str) -> bool:
    """Keys whose only use is being imported: Python keys of rosdep and ROS Python packages."""
    if key in NEVER_IMPORTED or key.startswith("ament_"):
        return False
    python_key = key.startswith("python3-") or key.endswith("-pip")
    return (python_key and bool(modules_of_key(key))) or looks_like_ros(key)


@rule("DEP006", "unused-dependency", Severity.INFO,
      fix="Remove the dependency from package.xml if nothing needs it")
def unused_dependency(package: Package) -> Iterator[Hit]:
    """A run-time dependency is declared but nothing in the package uses it.

    ## What it does
    Reports `<depend>`/`<exec_depend>` keys of Python modules and ROS Python packages that no
    module, test or launch file of an ament_python package imports, launches or mentions (a
    metapackage counts as used when a package it brings in is).
    Also reports a key named as a standard library module the code imports (`time`,
    `sqlite3`): the module needs no dependency, and the key installs a program instead (GNU
    time, the sqlite3 shell). Keys used by tools rather
    than imports (`ros2launch`, `launch_ros`, `rosidl_default_runtime`, `ament_*`,
    `python3-pytest`, ...) are never reported, nor are interface packages when the package has
    configuration files that may name their types.

    ## Why is this bad?
    Every declared dependency is installed on every machine that installs the package and
    lengthens builds; stale entries also hide which dependencies really matter.

    ## Example
    ```xml
    <depend>geometry_msgs</depend>  <!-- nothing imports geometry_msgs -->
    ```

    ## Use instead
    Remove the line, or import what you meant to use.
    """
    build_type = package.manifest.build_type if package.manifest else None
    if build_type is None or build_type.value != "ament_python":
        return
    used: set[str] = set()
    modules = all_python(package)
    for module in modules:
        for need in needs(package, module, guarded=None):
            used.update(need.keys)
            used.add(misspelt_package(package, need) or "")  # `sensors_msgs` means it
    used.update(launched_packages(package))
    texts = "\n".join(t for p, t in package.texts.items() if p != "package.xml")
    has_config = any(p.endswith(_CONFIG_SUFFIXES) and p != "package.xml" for p in package.files)
    imported = {i.top_level for module in modules for i in module.imports}
    for key, dependency in declared(package, RUNTIME, bringing=False).items():
        if key in STDLIB_NAMED_KEYS and key in imported and not dependency.condition:
            yield Hit(dependency.span, f"`{key}` is declared for the standard library module "
                      f"`{key}`, which needs no dependency: the rosdep key `{key}` installs "
                      f"{STDLIB_NAMED_KEYS[key]}", f"Remove this `<{dependency.tag}>` unless "
                      "the package runs that program")
            continue
        if (dependency.condition or key in used or brought_in(key) & used
                or not _import_only(key)
                or (has_config and looks_like_ros(key)) or _mentioned(key, texts)):
            continue
        yield Hit(dependency.span, f"`{key}` is declared but nothing imports or launches it")


def _mentioned(key: str, texts: str) -> bool:
    return any(re.search(rf"\b{re.escape(name)}\b", texts, re.IGNORECASE)
               for name in _import_names(key))
