"""Which package.xml key provides an import, and which keys are not rosdep keys.

Third-party modules map to rosdep keys through rosdep's own data
(:func:`pkgtool.knowledge.rosdistro.keys_for_import`); a module rosdep has no key for is
reported as unknown, never mapped. ROS import names map to the ROS package of the same name
unless listed in :data:`ROS_MODULE_PACKAGES`. The tables here hold what no data source decides.
"""

from __future__ import annotations

from functools import cache

from pkgtool.knowledge.rosdistro import DEFAULT_DISTRO, keys_for_import, stdlib_modules
from pkgtool.knowledge.tables import FLAGS, read

ALTERNATIVE_KEYS: dict[str, tuple[str, ...]] = {
    "PyKDL": ("python_orocos_kdl_vendor",),
}
"""ROS packages that also provide a third-party import (accepted, never suggested)."""

COVERED_BY: dict[str, frozenset[str]] = {
    "ament_lint_common": frozenset({
        "ament_copyright", "ament_cppcheck", "ament_cpplint", "ament_flake8", "ament_lint",
        "ament_lint_cmake", "ament_pep257", "ament_uncrustify", "ament_xmllint"}),
}
"""Packages whose declaration brings others along: ``ament_lint_common`` depends on the
``ament_cmake_*`` linters, and they on the Python linters that test files import."""

STDLIB_NAMED_KEYS: dict[str, str] = {
    "time": "GNU time, a command-line program",
    "sqlite3": "the sqlite3 command-line shell",
}
"""rosdep keys named as a module of Python's standard library, with what the key installs
(not that module: the standard library needs no dependency)."""

ROS_MODULE_PACKAGES: dict[str, str] = {
    "tf2_ros": "tf2_ros_py",
    "urdf_parser_py": "urdfdom_py",
    "moveit": "moveit_py",
    "hri": "pyhri",  # ament_python_install_package(hri); the released `hri` is libhri's C++
    "camera_info_manager": "camera_info_manager_py",  # image_common; the other is C++ only
    "scripts": "gazebo_ros",  # ament_python_install_package(scripts): `GazeboRosPaths`
}
"""ROS import names whose package has another name (every other ROS import is its package).
Most of them are Python bindings whose module takes the name of the C++ package they wrap."""

NOT_ROSDEP_KEYS: dict[str, str] = {
    # pip distribution names and import names: rosdep has no such keys
    "numpy": "python3-numpy",
    "scipy": "python3-scipy",
    "opencv-python": "python3-opencv",
    "opencv-python-headless": "python3-opencv",
    "opencv-contrib-python": "python3-opencv",
    "opencv": "python3-opencv",
    "opencv2": "python3-opencv",  # ROS 1's key
    "cv2": "python3-opencv",
    "pyyaml": "python3-yaml",
    "PyYAML": "python3-yaml",
    "pillow": "python3-pil",
    "Pillow": "python3-pil",
    "PIL": "python3-pil",
    "pyserial": "python3-serial",
    "matplotlib": "python3-matplotlib",
    "pandas": "python3-pandas",
    "scikit-learn": "python3-sklearn",
    "sklearn": "python3-sklearn",
    "scikit-image": "python3-skimage",
    "requests": "python3-requests",
    "pytest": "python3-pytest",
    "transforms3d": "python3-transforms3d",
    "psutil": "python3-psutil",
    "setuptools": "python3-setuptools",
    # ROS 1 era Python 2 keys: no definition for the Ubuntu releases ROS 2 targets
    "python-opencv": "python3-opencv",
    "python-numpy": "python3-numpy",
    "python-yaml": "python3-yaml",
    "python-pytest": "python3-pytest",
    "python-setuptools": "python3-setuptools",
    "OpenCV": "python3-opencv",  # CMake's name; MAN018 offers libopencv-dev to C++ packages
    # modules of rclpy named as packages (rclpy.lifecycle, rclpy.action): rclpy has them
    "rclpy_lifecycle": "rclpy",
    "rclpy_action": "rclpy",
    "rclpy_actions": "rclpy",
}
"""Names people write where a rosdep key belongs -> the key to use instead.

``yaml`` and ``serial`` are not listed: ``yaml`` is a real key (the libyaml C library) and
``serial`` is a ROS package in some distributions.
"""

CMAKE_NAMES: dict[str, str] = {
    "Eigen3": "eigen", "Eigen": "eigen", "CURL": "libcurl-dev", "Boost": "boost",
    "Qt5": "qtbase5-dev", "Qt6": "qt6-base-dev", "GTest": "gtest", "OpenSSL": "libssl-dev",
    "ZLIB": "zlib", "Ceres": "libceres-dev", "Protobuf": "protobuf-dev",
    "PkgConfig": "pkg-config", "nlohmann_json": "nlohmann-json-dev", "TBB": "tbb",
    "PythonLibs": "python3-dev", "Python3": "python3-dev", "YAML_CPP": "yaml-cpp",
    "X11": "libx11-dev", "LibXml2": "libxml2", "GeographicLib": "geographiclib",
    "PROJ": "proj", "SQLite3": "sqlite3", "FFTW3": "libfftw3", "Armadillo": "armadillo",
    "LAPACK": "liblapack-dev", "BLAS": "libblas-dev", "TinyXML2": "tinyxml2",
    "TinyXML": "tinyxml", "PCL": "libpcl-all-dev", "OpenCV": "libopencv-dev",
}
"""The names CMake's ``find_package()`` finds system libraries by, which people declare in
package.xml -> the rosdep key of the library (each checked against rosdep's data: no key and no
released package has the CMake name). :data:`NOT_ROSDEP_KEYS` comes first: ``OpenCV`` in a Python
package means ``python3-opencv``."""

ROS1_PACKAGES: dict[str, str] = {
    "rospy": "`rclpy`", "roscpp": "`rclcpp`", "roslib": "`ament_index_python`",
    "roslaunch": "`launch` and `launch_ros`", "rostest": "`launch_testing_ros`",
    "rosbag": "`rosbag2_py`", "tf": "`tf2_ros`", "actionlib": "`rclpy.action`",
    "dynamic_reconfigure": "node parameters", "message_generation": "`rosidl_default_generators`",
    "message_runtime": "`rosidl_default_runtime`",
    "catkin": "`<build_type>ament_python</build_type>` in `<export>`",
}
"""ROS 1 packages (and their Python modules) that no ROS 2 distribution has -> what replaces them.

``rospy``'s rosdep key resolves only on ROS 1 distributions; ROS 2 has none of these packages.
"""

NOT_PACKAGES: dict[str, str] = {
    "ament_python": "ament_python is a build type, not a package: declare "
                    "<build_type>ament_python</build_type> in <export> and drop the tag",
}
"""Build tools that are not packages at all, as buildtool_depend values."""


@cache
def brought_in(name: str) -> frozenset[str]:
    """Every package a declared ``name`` brings in: :data:`COVERED_BY`'s, and a released
    metapackage's run dependencies (``data/metapackages.txt``), through nested metapackages
    only (a regular package's own dependencies are its business, and may change)."""
    members = read("metapackages").values
    found = set(COVERED_BY.get(name, ()))
    pending, seen = [name], {name}
    while pending:
        for member in members.get(pending.pop(), "").split():
            found.add(member)
            if member in members and member not in seen:
                seen.add(member)
                pending.append(member)
    found.discard(name)
    return frozenset(found)


def is_metapackage(name: str) -> bool:
    """True for a released metapackage (``perception``, ``desktop``): it holds no code, so no
    import is ever its."""
    return name in read("metapackages").values


def metapackage_members(name: str, distro: str) -> tuple[str, ...] | None:
    """The packages a metapackage released for ``distro`` brings in directly (it installs
    nothing of its own: no module, no executable), or None for any other name."""
    table = read("metapackages")
    if name not in table.values or FLAGS.get(distro, "?") not in table.flags.get(name, ""):
        return None
    return tuple(table.values[name].split())


def key_for_python_module(top_level: str, distro: str = DEFAULT_DISTRO) -> str | None:
    """The rosdep key providing a third-party top-level import, or None if rosdep has none."""
    keys = keys_for_import(top_level, distro)
    return keys[0] if keys else None


def suggested_key(declared: str) -> str | None:
    """The rosdep key to use instead of ``declared`` when that is a pip/ROS 1 name."""
    return NOT_ROSDEP_KEYS.get(declared) or CMAKE_NAMES.get(declared)


def package_for_ros_module(top_level: str) -> str:
    """The ROS package providing a ROS import (usually the same name)."""
    return ROS_MODULE_PACKAGES.get(top_level, top_level)


def accepted_keys(top_level: str, primary: str) -> tuple[str, ...]:
    """Every key that provides ``top_level``: ``primary`` first, then the alternatives."""
    return (primary, *ALTERNATIVE_KEYS.get(top_level, ()))


__all__ = ["ALTERNATIVE_KEYS", "CMAKE_NAMES", "COVERED_BY", "NOT_PACKAGES", "NOT_ROSDEP_KEYS",
           "ROS1_PACKAGES", "ROS_MODULE_PACKAGES", "accepted_keys", "brought_in",
           "key_for_python_module", "package_for_ros_module", "stdlib_modules", "suggested_key"]
