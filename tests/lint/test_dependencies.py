"""Imports versus package.xml (DEP) and launch files (LCH), on packages built in memory."""

from __future__ import annotations

from pathlib import Path

import pytest

from pkgtool.model.cmake_install import installed_sources
from pkgtool.model.context import Context, WorkspacePackage
from pkgtool.model.package import Package
from pkgtool.rules.imports import classify, installed_code, misspelt_package, needs, own_modules
from pkgtool.rules import test_modules
from tests.helpers import MINIMAL_MANIFEST, codes, findings, make_package

SETUP = """
from setuptools import find_packages, setup

setup(
    name='demo',
    version='0.1.0',
    packages=find_packages(exclude=['test']),
    data_files=[('share/demo', ['package.xml'])],
    entry_points={'console_scripts': ['talker = demo.talker:main']},
)
"""


def _manifest(*extra: str) -> str:
    lines = "\n  ".join(extra)
    return MINIMAL_MANIFEST.format(name="demo").replace(
        "<test_depend>", f"{lines}\n  <test_depend>", 1)


def _package(tmp_path: Path, files: dict[str, str], *deps: str) -> Package:
    tree = {"package.xml": _manifest(*deps), "setup.py": SETUP, "demo/__init__.py": "",
            "resource/demo": ""}
    tree.update(files)
    return make_package(tmp_path / "demo", tree)


@pytest.mark.parametrize(("top", "kind", "key"), [
    ("cv2", "third-party", "python3-opencv"),
    ("yaml", "third-party", "python3-yaml"),
    ("tkinter", "third-party", "python3-tk"),
    ("sensor_msgs", "ros", "sensor_msgs"),
    ("my_robot_interfaces", "ros", "my_robot_interfaces"),
    ("tf2_ros", "ros", "tf2_ros_py"),
    ("camera_info_manager", "ros", "camera_info_manager_py"),
    ("urdf_parser_py", "ros", "urdfdom_py"),
    ("rclpy", "ros", "rclpy"),
    ("tf_transformations", "ros", "tf_transformations"),
    ("pyquaternion", "unknown", "python3-pyquaternion"),
    ("Some_Lib", "unknown", "python3-some-lib"),
])
def test_classify(top: str, kind: str, key: str) -> None:
    found_kind, keys = classify(top, ())
    assert (found_kind, keys[0]) == (kind, key)


def test_a_declared_name_is_a_package_not_unknown() -> None:
    assert classify("my_helpers", {"my_helpers"}) == ("ros", ("my_helpers",))


@pytest.mark.parametrize(("top", "kind"), [("simple_pid", "third-party"),
                                           ("tf_transformations", "ros")])
def test_a_workspace_package_providing_the_module_comes_first(top: str, kind: str) -> None:
    context = Context(workspace={"pid_src": WorkspacePackage("pid_src", modules=frozenset({top}))})
    found_kind, keys = classify(top, (), context)
    assert found_kind == kind
    assert keys[0] == "pid_src" and keys[1:] == classify(top, ())[1]


def test_an_interface_package_of_the_workspace_provides_its_generated_module() -> None:
    types = WorkspacePackage("arm_types", interfaces={"msg": frozenset({"JointGoal"})})
    no_interfaces = WorkspacePackage("arm_notes")
    context = Context(workspace={"arm_types": types, "arm_notes": no_interfaces})
    assert classify("arm_types", (), context) == ("ros", ("arm_types",))
    assert classify("arm_notes", (), context)[0] == "unknown"


def test_stdlib_own_and_sibling_imports_need_nothing(tmp_path: Path) -> None:
    package = _package(tmp_path, {
        "demo/talker.py": "import os\nimport json\nfrom demo import util\nimport util\n"
                          "from . import util as u\nimport launchlib\n",
        "demo/util.py": "",
        "launchlib/__init__.py": "",
    })
    module = package.module("demo/talker.py")
    assert module is not None
    assert [n.top for n in needs(package, module)] == []
    assert {"demo", "launchlib"} <= own_modules(package)


def test_a_launch_folder_does_not_hide_the_launch_package(tmp_path: Path) -> None:
    package = _package(tmp_path, {"launch/demo.launch.py": "from launch import Action\n",
                                  "launch/helpers.py": ""})
    assert "launch" not in own_modules(package)


def test_cmake_installed_python_packages_are_own_modules(tmp_path: Path) -> None:
    cmake = ("project(demo)\n# ament_python_install_package(commented_out)\n"
             "ament_python_install_package(${PROJECT_NAME})\n"
             "ament_python_install_package(\n  steps PACKAGE_DIR python/steps)\n"
             "pybind11_add_module(_planner src/bindings.cpp)\n")
    package = make_package(tmp_path / "demo", {
        "package.xml": _manifest(), "CMakeLists.txt": cmake, "python/steps/__init__.py": ""})
    assert {"demo", "steps", "_planner"} <= own_modules(package)
    assert "commented_out" not in own_modules(package)


@pytest.mark.parametrize(("cmake", "expected"), [
    ("project(demo)\ninstall(DIRECTORY launch ${CMAKE_CURRENT_SOURCE_DIR}/scripts/\n"
     "  DESTINATION share/${PROJECT_NAME} PATTERN *.pyc EXCLUDE)\n"
     "install(PROGRAMS tools/run.py DESTINATION lib/${PROJECT_NAME})\n"
     "ament_python_install_package(steps PACKAGE_DIR python/steps)\n"
     "ament_python_install_package(${PROJECT_NAME})\n"
     "ament_auto_package(INSTALL_TO_SHARE config rviz USE_SCOPED_HEADER_INSTALL_DIR)\n",
     {"launch", "scripts", "tools/run.py", "python/steps", "demo", "config", "rviz"}),
    ("project(demo)\ninstall(DIRECTORY ${EXTRA_DIR} DESTINATION share/demo)\n", None),
    ("project(demo)\nadd_subdirectory(python)\n", None),
    ("project(demo)\nfunction(install_tools)\nendfunction()\n", None),
])
def test_installed_sources_of_cmake(cmake: str, expected: set[str] | None) -> None:
    found = installed_sources(cmake)
    assert found == (None if expected is None else frozenset(expected))


def test_python_folder_cmake_never_installs_is_not_installed_code(tmp_path: Path) -> None:
    cmake = ("project(demo)\nament_python_install_package(${PROJECT_NAME})\n"
             "ament_add_pytest_test(t test APPEND_ENV PYTHONPATH=${CMAKE_SOURCE_DIR}/scripts)\n")
    package = make_package(tmp_path / "demo", {
        "package.xml": _manifest().replace(">ament_python<", ">ament_cmake<"),
        "CMakeLists.txt": cmake, "demo/__init__.py": "", "scripts/bag_tools/__init__.py": "",
        "generator/__init__.py": ""})
    assert [m.path for m in installed_code(package)] == ["demo/__init__.py"]


def test_installed_code_follows_setup_py(tmp_path: Path) -> None:
    package = _package(tmp_path, {
        "demo/talker.py": "", "demo/sub/__init__.py": "", "demo/sub/x.py": "",
        "test/test_a.py": "", "examples/e.py": "", "demo/test_helpers.py": "def test_a(): pass\n",
        "demo/bench_test.py": "class BenchTest:\n    def run(self):\n        pass\n",
    })
    assert sorted(m.path for m in installed_code(package)) == [
        "demo/__init__.py", "demo/bench_test.py", "demo/sub/__init__.py", "demo/sub/x.py",
        "demo/talker.py"]


def test_installed_module_named_like_a_test_is_a_test_only_if_pytest_runs_it(
        tmp_path: Path) -> None:
    test = "def test_a():\n    pass\n"
    package = _package(tmp_path, {
        "pytest.ini": "[pytest]\npython_files = check_*.py\n", "demo/test_a.py": test,
        "demo/check_b_test.py": test, "demo/conftest.py": "", "demo/tests/__init__.py": "",
        "demo/tests/helper_test.py": ""})
    assert sorted(test_modules.test_files(package)) == [
        "demo/check_b_test.py", "demo/conftest.py", "demo/tests/helper_test.py"]


def test_installed_code_without_setup_py_uses_package_folders(tmp_path: Path) -> None:
    package = make_package(tmp_path / "demo", {
        "package.xml": _manifest(), "demo/__init__.py": "", "demo/talker.py": "import cv2\n",
        "tools/script.py": "import pandas\n"})
    assert [m.path for m in installed_code(package)] == ["demo/__init__.py", "demo/talker.py"]
    assert codes(package, "DEP001") == ["DEP001"]


def test_nothing_is_reported_without_a_readable_package_xml(tmp_path: Path) -> None:
    package = make_package(tmp_path / "demo", {
        "package.xml": "<package><name>demo</nam></package>", "setup.py": SETUP,
        "demo/__init__.py": "", "demo/talker.py": "import cv2\n",
        "test/test_a.py": "import yaml\n",
        "launch/a.launch.py": "from launch_ros.actions import Node\nNode(package='x')\n"})
    assert codes(package, "DEP001", "DEP002", "DEP003", "DEP004", "DEP005", "DEP006",
                 "LCH002", "LCH003") == []


def test_tf2_ros_module_needs_the_python_package_not_the_cpp_one(tmp_path: Path) -> None:
    python = _package(tmp_path / "py", {"demo/talker.py": "import tf2_ros\n"},
                      "<exec_depend>tf2_ros_py</exec_depend>")
    assert codes(python, "DEP001") == []
    cpp = _package(tmp_path / "cpp", {"demo/talker.py": "import tf2_ros\n"},
                   "<exec_depend>tf2_ros</exec_depend>")
    [finding] = findings(cpp, "DEP001")
    assert "`tf2_ros` is declared, but that package does not provide the Python module: " \
        "`tf2_ros_py` does" in finding.message
    assert finding.fix == "Add `<exec_depend>tf2_ros_py</exec_depend>` to package.xml"


def test_one_finding_per_imported_package_and_file(tmp_path: Path) -> None:
    package = _package(tmp_path, {"demo/talker.py": "from sensor_msgs.msg import Imu\n"
                                                    "from sensor_msgs.msg import Image\n"})
    assert [f.span.line for f in findings(package, "DEP001")] == [1]


def test_modules_of_one_key_are_one_finding_naming_them_all(tmp_path: Path) -> None:
    package = _package(tmp_path, {
        "demo/talker.py": "import matplotlib.pyplot\nfrom mpl_toolkits.mplot3d import Axes3D\n",
        "demo/viewer.py": "from mpl_toolkits import mplot3d\n"})
    [finding] = findings(package, "DEP001")
    assert (finding.span.path, finding.span.line) == ("demo/talker.py", 1)
    assert [(s.path, s.line) for s in finding.related] == [
        ("demo/talker.py", 2), ("demo/viewer.py", 1)]
    assert finding.message.startswith(
        "`matplotlib` and `mpl_toolkits` are imported but `python3-matplotlib`, which provides "
        "them, is not declared in package.xml; also imported in `demo/talker.py:2` "
        "(`mpl_toolkits`)")
    assert finding.fix == "Add `<exec_depend>python3-matplotlib</exec_depend>` to package.xml"


def test_modules_of_one_key_only_tested_are_one_finding(tmp_path: Path) -> None:
    package = _package(tmp_path, {"demo/talker.py": "import matplotlib\nimport mpl_toolkits\n"},
                       "<test_depend>python3-matplotlib</test_depend>")
    assert [f.message for f in findings(package, "DEP001")] == [
        "`matplotlib` and `mpl_toolkits` are imported by installed code but "
        "`python3-matplotlib`, which provides them, is only a `test_depend`; also imported in "
        "`demo/talker.py:2` (`mpl_toolkits`)"]


@pytest.mark.parametrize("code", [
    "import numpy\nimport scipy\n",  # two keys
    "import pkg_resources\nimport setuptools\n",  # each suggests its own key
    "import pyquaternion\nimport Pyquaternion\n",  # one guessed key: DEP004, never joined
    "import my_robot_msgs\nimport my_robot_srvs\n",  # ROS names, each its own package
])
def test_modules_of_different_or_unknown_keys_stay_apart(tmp_path: Path, code: str) -> None:
    package = _package(tmp_path, {"demo/talker.py": code})
    found = findings(package, "DEP001", "DEP004")
    assert [f.span.line for f in found] == [1, 2]
    assert not any(f.related for f in found)


def test_build_depend_covers_test_imports(tmp_path: Path) -> None:
    package = _package(tmp_path, {"test/test_a.py": "import numpy\nimport pytest\n"},
                       "<build_depend>python3-numpy</build_depend>")
    assert codes(package, "DEP003") == []


def test_test_helpers_next_to_tests_are_own_modules(tmp_path: Path) -> None:
    package = _package(tmp_path, {"test/test_a.py": "import helpers\nimport pytest\n",
                                  "test/helpers.py": ""})
    assert codes(package, "DEP003", "DEP004") == []


def test_guarded_and_unguarded_import_of_the_same_module_is_one_error(tmp_path: Path) -> None:
    package = _package(tmp_path, {"demo/talker.py": "import cv2\ntry:\n    import cv2\n"
                                                    "except ImportError:\n    pass\n"})
    assert codes(package, "DEP001", "DEP005") == ["DEP001"]


def test_unused_dependency_ignores_conditions_tools_and_mentions(tmp_path: Path) -> None:
    package = _package(tmp_path, {"demo/talker.py": "NAME = 'std_msgs/msg/String'\n"},
                       '<exec_depend condition="$ROS_VERSION == 1">rospy_msgs</exec_depend>',
                       "<exec_depend>std_msgs</exec_depend>",
                       "<exec_depend>ament_index_python</exec_depend>",
                       "<exec_depend>ros2launch</exec_depend>",
                       "<exec_depend>ffmpeg</exec_depend>")
    assert [f.message for f in findings(package, "DEP006")] == [
        "`rclpy` is declared but nothing imports or launches it"]


def test_unused_dependency_sees_launch_files(tmp_path: Path) -> None:
    package = _package(tmp_path, {
        "demo/talker.py": "import rclpy\n",
        "launch/a.launch.py": "Node(package='turtlesim', executable='turtlesim_node')\n"},
        "<exec_depend>turtlesim</exec_depend>", "<exec_depend>nav_msgs</exec_depend>")
    assert [f.message for f in findings(package, "DEP006")] == [
        "`nav_msgs` is declared but nothing imports or launches it"]


def test_launch_executable_from_setup_cfg_entry_points(tmp_path: Path) -> None:
    package = make_package(tmp_path / "demo", {
        "package.xml": _manifest(), "demo/__init__.py": "",
        "setup.py": "from setuptools import setup\nsetup(name='demo')\n",
        "setup.cfg": "[options.entry_points]\nconsole_scripts =\n    listener = demo.l:main\n",
        "launch/a.launch.py": "Node(package='demo', executable='listener')\n"
                              "Node(package='demo', executable='talker')\n"})
    assert [f.span.line for f in findings(package, "LCH001")] == [2]


@pytest.mark.parametrize("setup", [
    "from setuptools import setup\nsetup(name='demo', entry_points=make_entry_points())\n",
    "from setuptools import setup\nsetup(name='demo', scripts=['bin/talker_node'])\n",
    "from setuptools import setup\nsetup(**options)\n",
])
def test_launch_executables_unknown_when_setup_py_is_dynamic(tmp_path: Path, setup: str) -> None:
    package = make_package(tmp_path / "demo", {
        "package.xml": _manifest(), "demo/__init__.py": "", "setup.py": setup,
        "launch/a.launch.py": "Node(package='demo', executable='talker_node')\n"})
    assert codes(package, "LCH001") == []


def test_launch_file_of_tests_may_use_test_dependencies(tmp_path: Path) -> None:
    package = _package(
        tmp_path,
        {"test/test_launch.launch.py": "import launch_testing\nimport launch\n"
                                       "Node(package='turtlesim', executable='t')\n"},
        "<test_depend>turtlesim</test_depend>", "<test_depend>launch_testing</test_depend>",
        "<exec_depend>ros2launch</exec_depend>")
    assert codes(package, "LCH002", "LCH003") == []


def test_own_package_in_launch_files_is_never_undeclared(tmp_path: Path) -> None:
    package = _package(tmp_path, {"launch/a.launch.xml":
                                  '<launch><node pkg="demo" exec="talker"/>'
                                  '<include file="$(find-pkg-share demo)/launch/b.launch.py"/>'
                                  "</launch>"})
    assert codes(package, "LCH001", "LCH002") == []


def test_a_package_one_edit_from_a_released_one_is_a_typo_of_it(tmp_path: Path) -> None:
    package = _package(tmp_path, {"demo/talker.py": (
        "from sensors_msgs.msg import Imu\nfrom grbl_interfaces.msg import State\n"
        "from turtlebot5_msgs.msg import Dock\n")}, "<exec_depend>sensor_msgs</exec_depend>")
    module = next(m for m in package.modules if m.path == "demo/talker.py")
    meant = {need.top: misspelt_package(package, need) for need in needs(package, module)}
    assert meant == {"sensors_msgs": "sensor_msgs", "grbl_interfaces": None,
                     "turtlebot5_msgs": None}  # two edits from rcl_interfaces; a number


def test_a_launched_package_of_a_submodule_not_checked_out_is_named_so(tmp_path: Path) -> None:
    (tmp_path / ".git").mkdir()
    (tmp_path / "vectornav").mkdir()
    (tmp_path / ".gitmodules").write_text(
        '[submodule "vectornav"]\n\tpath = vectornav\n\turl = https://example.com/vn\n')
    package = _package(tmp_path, {"launch/a.launch.py": (
        "from launch_ros.actions import Node\n\n\ndef generate_launch_description():\n"
        "    return LaunchDescription([Node(package='vectornav', executable='vn')])\n")})
    [finding] = findings(package, "LCH002")
    assert finding.message.endswith("it is probably the package of the git submodule "
                                    "`vectornav`, which is not checked out here")
