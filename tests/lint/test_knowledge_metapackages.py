"""The metapackage criterion of the generator on in-memory trees, and the shipped table."""

from __future__ import annotations

from pkgtool.knowledge.generate_metapackages import installs_nothing, metapackages
from pkgtool.knowledge.rosdep import brought_in
from pkgtool.knowledge.tables import read

CMAKE_META = """cmake_minimum_required(VERSION 3.16)
project(bundle)
find_package(ament_cmake REQUIRED)  # nothing else
ament_package()
"""
CMAKE_INSTALLING = CMAKE_META.replace("ament_package()", "install(DIRECTORY launch\n"
                                      "  DESTINATION share/${PROJECT_NAME})\nament_package()")


def _manifest(name: str, *depends: str, export: str = "") -> bytes:
    tags = "".join(f"<{tag}>{dep}</{tag}>" for tag, dep in depends)
    return (f'<?xml version="1.0"?><package format="3"><name>{name}</name>{tags}'
            f"<export>{export}</export></package>").encode()


def _found(tree: dict[str, bytes | str]) -> dict[str, list[str]]:
    def show(path: str) -> bytes:
        value = tree[path]
        return value.encode() if isinstance(value, str) else value
    return dict(metapackages(tree, show))


def test_a_folder_of_bookkeeping_only_is_a_metapackage_with_its_run_dependencies() -> None:
    tree = {
        "bundle/package.xml": _manifest("bundle", ("buildtool_depend", "ament_cmake"),
                                        ("exec_depend", "member_a"), ("depend", "member_b"),
                                        ("test_depend", "ament_lint_auto"),
                                        ("build_depend", "member_c")),
        "bundle/CMakeLists.txt": CMAKE_META, "bundle/CHANGELOG.rst": "",
        "bundle/rosdoc2.yaml": "", "bundle/doc/index.rst": "",
        "member_a/package.xml": _manifest("member_a", ("exec_depend", "rclpy")),
        "member_a/setup.py": "", "member_a/member_a/__init__.py": "",
    }
    assert _found(tree) == {"bundle": ["member_a", "member_b"]}


def test_code_or_data_of_its_own_makes_a_regular_package() -> None:
    tree = {
        "publisher/package.xml": _manifest("publisher", ("exec_depend", "rclpy")),
        "publisher/CMakeLists.txt": CMAKE_INSTALLING, "publisher/setup.py": "",
        "publisher/src/publisher/__init__.py": "",
        "viewer/package.xml": _manifest("viewer", ("exec_depend", "rviz2")),
        "viewer/CMakeLists.txt": CMAKE_INSTALLING, "viewer/rviz/view.rviz": "",
    }
    assert _found(tree) == {}


def test_exported_metapackage_launch_files_and_uninstalled_scripts_count() -> None:
    tree = {
        "exported/package.xml": _manifest("exported", ("run_depend", "member_a"),
                                          export="<metapackage/>"),
        "exported/CMakeLists.txt": "catkin_metapackage()", "exported/data/x.yaml": "",
        "launching/package.xml": _manifest("launching", ("exec_depend", "member_b")),
        "launching/CMakeLists.txt": CMAKE_INSTALLING, "launching/launch/all-launch.py": "",
        "scripted/package.xml": _manifest("scripted", ("exec_depend", "member_c")),
        "scripted/CMakeLists.txt": CMAKE_META, "scripted/scripts/make_table.py": "",
        "empty/package.xml": _manifest("empty", ("build_depend", "member_d")),
        "empty/CMakeLists.txt": CMAKE_META,
    }
    assert _found(tree) == {"exported": ["member_a"], "launching": ["member_b"],
                            "scripted": ["member_c"]}


def test_nested_and_ignored_packages_are_not_the_outer_folders_files() -> None:
    tree = {
        "stack/package.xml": _manifest("stack", ("exec_depend", "stack_core")),
        "stack/CMakeLists.txt": CMAKE_META,
        "stack/stack_core/package.xml": _manifest("stack_core", ("exec_depend", "rclcpp")),
        "stack/stack_core/src/core.cpp": "",
        "old/COLCON_IGNORE": "", "old/package.xml": _manifest("old", ("exec_depend", "x")),
    }
    assert _found(tree) == {"stack": ["stack_core"]}


def test_cmake_that_installs_extras_is_no_metapackage_build() -> None:
    assert installs_nothing(CMAKE_META)
    assert not installs_nothing(CMAKE_INSTALLING)
    assert not installs_nothing(CMAKE_META.replace("ament_package()",
                                                   "ament_package(CONFIG_EXTRAS x.cmake)"))


def test_the_shipped_table_parses_and_names_its_sources() -> None:
    table = read("metapackages")
    assert "controller_manager" in table.values["ros2_control"].split()
    assert table.source.split()[1] and len(table.source.split()[1]) == 40
    assert "joint_state_publisher" not in table.flags


def test_brought_in_follows_nested_metapackages_only() -> None:
    assert "moveit_ros_move_group" in brought_in("moveit")
    assert {"velodyne_driver", "ros_gz_sim", "controller_manager"} <= (
        brought_in("velodyne") | brought_in("ros_gz") | brought_in("ros2_control"))
    assert "ament_flake8" in brought_in("ament_lint_common")
    assert brought_in("joint_state_publisher") == frozenset()
    assert "rclpy" not in brought_in("ros2_control")
