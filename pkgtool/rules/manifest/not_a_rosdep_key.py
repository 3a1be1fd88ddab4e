"""MAN018: a dependency key that rosdep cannot resolve: pip names, ROS 1 keys, build types."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.lazy_regex import lazy_pattern
from pkgtool.knowledge.rosdep import CMAKE_NAMES, NOT_PACKAGES, ROS1_PACKAGES
from pkgtool.knowledge.rosdistro import is_released_package, is_rosdep_key, stdlib_modules
from pkgtool.model.condition import applies
from pkgtool.model.package import Package
from pkgtool.model.xml import XmlElement
from pkgtool.rules.dependency_names import (cmake_finds, interface_named, key_instead,
                                            names_a_file)
from pkgtool.rules.imports import declaration_cause
from pkgtool.rules.manifest.common import build_types, tree
from pkgtool.rules.manifest.schema import DEPENDS_1, DEPENDS_2, token
from pkgtool.rules.registry import rule

_CHECKED = frozenset(DEPENDS_1 + DEPENDS_2) - {"conflict", "replace"}
_SEPARATORS = lazy_pattern(r"[\s,;]+")
_KEY = lazy_pattern(r"[A-Za-z0-9][\w.+-]*")
_STRAY_EDGES = lazy_pattern(r"^[^A-Za-z0-9]+|[^\w+]+$")
"""Characters no key starts or ends with (``rclpy/``, ``'numpy'``, ``rclpy,``)."""
"""What a package name or rosdep key looks like."""
_STDLIB = frozenset({
    "abc", "argparse", "array", "asyncio", "base64", "collections", "concurrent", "copy", "csv",
    "dataclasses", "datetime", "enum", "functools", "glob", "hashlib", "heapq", "importlib",
    "inspect", "io", "itertools", "json", "logging", "math", "multiprocessing", "os", "pathlib",
    "pickle", "queue", "random", "re", "shutil", "signal", "socket", "statistics", "string",
    "struct", "subprocess", "sys", "tempfile", "threading", "traceback", "typing",
    "unittest", "urllib", "warnings",
})
"""Standard library modules students declare, and that are no rosdep key (``time`` is one, for
GNU time: rosdep resolves it, so it is DEP006's needless dependency, not this rule's); any
other standard library module counts when it is neither a rosdep key nor a released package
(``uuid``, ``zlib`` and ``sqlite3`` are keys)."""
_CPP_KEYS = {"opencv": "libopencv-dev", "opencv2": "libopencv-dev"}
"""The C++ library key for a name whose Python key MAN018 suggests elsewhere (and CMake's names
of libraries, :data:`~pkgtool.knowledge.rosdep.CMAKE_NAMES`: ``OpenCV``)."""


def several_keys(key: str) -> list[str]:
    """The keys of a dependency that lists several (``rclpy sensor_msgs``, ``a, b``); empty
    for one key."""
    parts = [part for part in _SEPARATORS.split(key) if part]
    return parts if len(parts) > 1 and all(_KEY.fullmatch(part) for part in parts) else []


def _hit(element: XmlElement, ros2: bool, compiled: bool, distro: str) -> Hit | None:
    key, tag = token(element.text), element.tag
    keys = several_keys(key)
    if keys:
        return Hit(element.span, f"`{key}` is {len(keys)} keys in one `<{tag}>`: rosdep and "
                   "colcon read it as one key, which does not exist, and depend on none of "
                   "them", "Write one tag per key: " +
                   ", ".join(f"`<{tag}>{part}</{tag}>`" for part in keys))
    owner, slash, rest = key.partition("/")
    if slash and rest and owner.replace("_", "").replace("-", "").isalnum():
        return Hit(element.span, f"`{key}` names something inside a package (an interface, a "
                   "file), not a package: rosdep cannot resolve it",
                   f"Write `<{tag}>{owner}</{tag}>`")
    if key and not _KEY.fullmatch(key):
        return _stray_characters(element, key)
    if key in NOT_PACKAGES:
        return Hit(element.span, f"`{key}` is a build type, not a package",
                   f"Remove this `<{tag}>` and declare `<build_type>{key}</build_type>` in "
                   "`<export>`")
    interface = interface_named(key, distro)
    if interface is not None:
        return Hit(element.span, f"`{key}` is {interface[0]} of `{interface[1]}`, not a "
                   "package: rosdep cannot resolve it", f"Write `<{tag}>{interface[1]}</{tag}>`",
                   cause=declaration_cause(tag, interface[1]))
    owner, _, kind = key.rpartition(".")
    if kind in ("msg", "srv", "action") and owner and \
            (is_released_package(owner, distro) or owner.endswith(("_msgs", "_interfaces"))):
        return Hit(element.span, f"`{key}` names the `{kind}` module of `{owner}` (what code "
                   "imports), not a package: rosdep cannot resolve it",
                   f"Write `<{tag}>{owner}</{tag}>`")
    if names_a_file(key, distro):
        return Hit(element.span, f"`{key}` is a file name, not a package: rosdep cannot "
                   "resolve it", f"Remove this `<{tag}>` (files of the package need no "
                   "dependency), or name the package that provides the file")
    if key in _STDLIB or key in stdlib_modules(distro) and not is_rosdep_key(key) and \
            not is_released_package(key, distro):
        return Hit(element.span, f"`{key}` is part of the Python standard library, not a rosdep "
                   "key", f"Remove this `<{tag}>`: the standard library needs no dependency")
    if key in ROS1_PACKAGES and ros2:
        return Hit(element.span, f"`{key}` is a ROS 1 package that ROS 2 does not have",
                   f"Replace it with {ROS1_PACKAGES[key]}")
    python = key_instead(key, distro, tag)
    if python is None:
        return None
    replacement = _CPP_KEYS.get(key) or CMAKE_NAMES.get(key, "") \
        if compiled and python.startswith("python3-") else python  # C++ code wants the library
    if not replacement:
        return Hit(element.span, f"`{key}` is not a rosdep key",
                   f"Write the rosdep key of what the package uses: `{python}` for Python "
                   "code, the library's `lib...-dev` key for C++")
    if key.startswith("python-"):
        what = "a ROS 1 (Python 2) key that rosdep cannot resolve on ROS 2's Ubuntu releases"
    else:
        what = f"not a rosdep key (the key is `{replacement}`)"
    return Hit(element.span, f"`{key}` is {what}",
               f"Write `<{tag}>{replacement}</{tag}>`",
               cause=declaration_cause(tag, replacement))


def _stray_characters(element: XmlElement, key: str) -> Hit:
    """The hit for a key holding a character no package name or rosdep key has."""
    tag, cleaned = element.tag, _STRAY_EDGES.sub("", key)
    return Hit(element.span, f"`{key}` holds characters no package name or rosdep key has: "
               "rosdep cannot resolve it, and colcon orders nothing by it",
               f"Write `<{tag}>{cleaned}</{tag}>`" if _KEY.fullmatch(cleaned) else
               "Write the package's name or rosdep key alone")


@rule("MAN018", "not-a-rosdep-key", Severity.ERROR,
      fix="Use the rosdep key, e.g. `python3-numpy`")
def not_a_rosdep_key(package: Package) -> Iterator[Hit]:
    """A dependency names a pip package, an import name, a ROS 1 key or a build type.

    ## What it does
    Reports dependency keys that are known not to be rosdep keys, with the key to use:
    several keys in one tag (``<depend>rclpy sensor_msgs</depend>``),
    a name with a ``/`` (``turtlesim/msg/Pose``: its package is the dependency), the name of
    an interface of one known package (``PoseStamped``: package names are lower case), a name with
    characters no key has (``rclpy/``, ``'numpy'``), a file name
    (``robot.launch.py``, ``params.yaml``),
    rclpy's own modules named as packages (``rclpy_lifecycle``: the key is ``rclpy``),
    pip distribution names (``opencv-python``, ``pyyaml``, ``numpy``), also after ``python3-``
    (``python3-pillow``: the key is ``python3-pil``), import names (``cv2``),
    ROS 1 Python 2 keys (``python-opencv``), ROS 1 packages (``rospy``, ``catkin``) in a package
    whose build type is ``ament_*``, ``ament_python``, which is a build type, and
    standard library modules (``math``, ``threading``, ``termios``), which need no
    dependency. In a package whose ``<build_type>`` is another than ``ament_python``
    (``ament_cmake``, ``cmake``), whose C++ code wants libraries, the key offered for
    ``opencv`` is ``libopencv-dev``, and none where only a Python key is known.
    A tag whose REP 149 ``condition`` is false for the target ROS 2 distribution (or not
    understood) is not used there and not checked, as packages for both ROS versions have:
    ``<exec_depend condition="$ROS_PYTHON_VERSION == 2">python-numpy</exec_depend>``.
    CMake's names of system libraries (``Eigen3``, ``OpenCV``, ``Boost``, ``CURL``) name
    the library's key (``eigen``, ``libopencv-dev``). Any other name that is a package of
    the workspace linted with this one, or that CMakeLists.txt finds with
    ``find_package(name)``, is a package built from source beside it (``serial`` cloned by a
    ``.repos`` file) and not checked.

    ## Why is this bad?
    ``rosdep install`` stops with "Cannot locate rosdep definition", build farms refuse the
    package, and the dependency is never installed on a fresh machine. ``ros2 pkg create
    --build-type ament_python`` adds no ``buildtool_depend`` at all.

    ## Example
    ```xml
    <buildtool_depend>ament_python</buildtool_depend>
    <exec_depend>opencv-python</exec_depend>
    <exec_depend>python-opencv</exec_depend>
    ```

    ## Use instead
    ```xml
    <exec_depend>python3-opencv</exec_depend>
    ```
    """
    found = tree(package)
    if found is None:
        return
    types = [b.text for b in build_types(found)]
    ros2 = any(t.startswith("ament_") for t in types)
    compiled = bool(types) and "ament_python" not in types  # CMake: C++ code, libraries
    for element in found.elements():
        key = token(element.text)
        if key in package.context.workspace and key not in NOT_PACKAGES or \
                cmake_finds(package, key) and key not in CMAKE_NAMES:
            continue  # a package built from source with this one (a workspace's, a .repos's)
        hit = _hit(element, ros2, compiled, package.context.distro) \
            if element.tag in _CHECKED and \
            applies(element.attribute("condition"), package.context.distro) else None
        if hit:
            yield hit
