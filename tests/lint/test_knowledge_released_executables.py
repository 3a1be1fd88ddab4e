"""The released-executables generator on in-memory trees, and the shipped table."""

from __future__ import annotations

from pkgtool.knowledge.generate_released_executables import package_executables
from pkgtool.knowledge.rosdistro import released_executables, released_installers

PYTHON_MANIFEST = ("<package format='3'><name>teleop</name>"
                   "<export><build_type>ament_python</build_type></export></package>")
CMAKE_MANIFEST = "<package format='3'><name>driver</name></package>"
SETUP = """from setuptools import setup
setup(name='teleop', packages=['teleop'],
      data_files=[('share/teleop', ['package.xml'])],
      entry_points={'console_scripts': ['teleop_node = teleop.main:main']})
"""
CMAKE = """cmake_minimum_required(VERSION 3.8)
project(driver)
find_package(ament_cmake REQUIRED)
add_executable(driver_node src/main.cpp)
install(TARGETS driver_node DESTINATION lib/${PROJECT_NAME})
ament_package()
"""


def _found(tree: dict[str, str]) -> dict[str, frozenset[str]]:
    return package_executables(sorted(tree), tree.get)


def test_console_scripts_and_installed_targets_are_read() -> None:
    tree = {"teleop/package.xml": PYTHON_MANIFEST, "teleop/setup.py": SETUP,
            "driver/package.xml": CMAKE_MANIFEST, "driver/CMakeLists.txt": CMAKE}
    assert _found(tree) == {"teleop": frozenset({"teleop_node"}),
                            "driver": frozenset({"driver_node"})}


def test_packages_whose_executables_are_not_certain_are_left_out() -> None:
    scripts = CMAKE.replace("ament_package()", "ament_python_install_package(${PROJECT_NAME}\n"
                            "  SCRIPTS_DESTINATION lib/${PROJECT_NAME})\nament_package()")
    own_function = CMAKE.replace("ament_package()", "add_driver_tools()\nament_package()")
    for cmake in (scripts, own_function):
        assert _found({"package.xml": CMAKE_MANIFEST, "CMakeLists.txt": cmake}) == {}
    assert _found({"package.xml": PYTHON_MANIFEST}) == {}  # no setup.py to read


def test_the_shipped_table_knows_common_packages_per_distribution() -> None:
    for distro in ("humble", "jazzy"):
        assert released_executables("robot_state_publisher", distro) == \
            frozenset({"robot_state_publisher"})
        assert "static_transform_publisher" in (released_executables("tf2_ros", distro) or ())
        assert released_installers("joint_state_publisher_gui", distro) == \
            ("joint_state_publisher_gui",)
    assert released_executables("my_robot_bringup") is None
    assert released_executables("robot_state_publisher", "kilted") is None
