"""Correct manifests in the forms real packages use give no MAN finding (false errors cost)."""

from __future__ import annotations

from pathlib import Path

import pytest

from pkgtool.findings import Severity
from pkgtool.model.package import load_package
from pkgtool.rules.registry import load_all
from tests.helpers import findings, make_package

MAN_RULES = tuple(code for code, rule in load_all().items()
                  if code.startswith("MAN") and rule.default_enabled)
REFERENCE = Path(__file__).resolve().parents[2] / "reference_packages"
PI = ('<?xml version="1.0"?>\n<?xml-model href="http://download.ros.org/schema/'
      'package_format3.xsd" schematypens="http://www.w3.org/2001/XMLSchema"?>\n')
SETUP_PY = "from setuptools import setup\n\nsetup(name='demo_pkg')\n"
CMAKE = "cmake_minimum_required(VERSION 3.8)\nproject(demo_pkg)\n"

ROS2_PKG_CREATE = PI + """<package format="3">
  <name>demo_pkg</name>
  <version>0.0.0</version>
  <description>{description}</description>
  <maintainer email="{email}">{user}</maintainer>
  <license>{license}</license>

  <depend>rclpy</depend>
  <depend>std_msgs</depend>

  <test_depend>ament_copyright</test_depend>
  <test_depend>ament_flake8</test_depend>
  <test_depend>ament_pep257</test_depend>
  <test_depend>python3-pytest</test_depend>

  <export>
    <build_type>ament_python</build_type>
  </export>
</package>
"""

MANIFESTS = {
    "ros2_pkg_create_with_options": (ROS2_PKG_CREATE.format(
        description="Publishes battery state", email="ada@example.com", user="Ada Lovelace",
        license="Apache-2.0"), ("setup.py",)),
    "format2_with_authors_like_ros2_demos": ("""<?xml version="1.0"?>
<package format="2">
  <name>demo_pkg</name>
  <version>0.7.7</version>
  <description>
    Python nodes used for demo purposes.
  </description>
  <maintainer email="ros@example.org">Maintainer One</maintainer>
  <license>Apache License 2.0</license>

  <author>First Author</author>
  <author email="second@example.org">Second Author</author>

  <build_depend>rclpy</build_depend>
  <exec_depend>example_interfaces</exec_depend>
  <exec_depend>rclpy</exec_depend>
  <test_depend>rclpy</test_depend>
  <test_depend>python3-pytest</test_depend>

  <export>
    <build_type>ament_python</build_type>
  </export>
</package>
""", ("setup.py",)),
    "everything_format3": (PI + """<package format="3"
    xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
    xsi:noNamespaceSchemaLocation="http://download.ros.org/schema/package_format3.xsd">
  <!-- Identity -->
  <name>demo_pkg</name>
  <version compatibility="1.0.0">1.2.0</version>
  <description>Drives the <em>demo</em> robot; see <a href="https://example.com">docs</a>.
  </description>
  <maintainer email="ada@example.com">Ada Lovelace</maintainer>
  <maintainer email="grace.hopper+ros@mail.example.co.uk">Grace Hopper</maintainer>
  <license file="LICENSE">Apache-2.0</license>
  <license file="third_party/LICENSE.bsd">BSD-3-Clause</license>

  <url type="website">https://index.ros.org/p/demo_pkg</url>
  <url type="repository">https://github.com/ada/demo_pkg</url>
  <url type="bugtracker">https://github.com/ada/demo_pkg/issues</url>
  <author email="alan@example.com">Alan Turing</author>
  <author>Anonymous Contributor</author>

  <buildtool_depend>ament_cmake_python</buildtool_depend>
  <depend version_gte="7.0.0">rclpy</depend>
  <exec_depend condition="$ROS_DISTRO != humble">tf2_ros_py</exec_depend>
  <exec_depend condition="$ROS_DISTRO == humble">tf2_ros</exec_depend>
  <exec_depend>python3-numpy</exec_depend>
  <exec_depend>python3-opencv</exec_depend>
  <exec_depend>python3-yaml</exec_depend>
  <doc_depend>python3-sphinx</doc_depend>
  <test_depend>python3-pytest</test_depend>
  <test_depend>launch_testing_ros</test_depend>

  <group_depend>demo_plugins</group_depend>
  <member_of_group>demo_tools</member_of_group>

  <export>
    <build_type>ament_python</build_type>
    <architecture_independent/>
    <rosdoc config="rosdoc.yaml"/>
    <deprecated>Use demo_pkg2 instead</deprecated>
  </export>
</package>
""", ("setup.py",)),
    "hybrid_ros1_ros2_with_conditions": (PI + """<package format="3">
  <name>demo_pkg</name>
  <version>2.0.1</version>
  <description>Works with ROS 1 and ROS 2</description>
  <maintainer email="ada@example.com">Ada</maintainer>
  <license>BSD-3-Clause</license>

  <buildtool_depend condition="$ROS_VERSION == 1">catkin</buildtool_depend>
  <buildtool_depend condition="$ROS_VERSION == 2">ament_cmake</buildtool_depend>
  <depend condition="$ROS_VERSION == 1">rospy</depend>
  <depend condition="$ROS_VERSION == 2">rclpy</depend>
  <exec_depend condition="$ROS_PYTHON_VERSION == 3">python3-numpy</exec_depend>

  <export>
    <build_type condition="$ROS_VERSION == 1">catkin</build_type>
    <build_type condition="$ROS_VERSION == 2">ament_cmake</build_type>
  </export>
</package>
""", ("setup.py", "CMakeLists.txt")),
    "interface_package": (PI + """<package format="3">
  <name>demo_msgs</name>
  <version>0.1.0</version>
  <description>Messages of the demo robot</description>
  <maintainer email="ada@example.com">Ada</maintainer>
  <license>MIT</license>

  <buildtool_depend>ament_cmake</buildtool_depend>
  <buildtool_depend>rosidl_default_generators</buildtool_depend>
  <depend>std_msgs</depend>
  <exec_depend>rosidl_default_runtime</exec_depend>
  <test_depend>ament_lint_common</test_depend>

  <member_of_group>rosidl_interface_packages</member_of_group>

  <export>
    <build_type>ament_cmake</build_type>
  </export>
</package>
""", ("CMakeLists.txt",)),
    "ros1_catkin_format2_without_build_type": ("""<?xml version="1.0"?>
<package format="2">
  <name>demo_pkg</name>
  <version>0.0.1</version>
  <description>The demo_pkg package</description>
  <!-- One maintainer tag required, multiple allowed, one person per tag -->
  <maintainer email="ada@example.com">Ada</maintainer>
  <!-- Commonly used license strings: BSD, MIT, GPLv3 -->
  <license>BSD</license>
  <buildtool_depend>catkin</buildtool_depend>
  <build_depend>rospy</build_depend>
  <build_export_depend>rospy</build_export_depend>
  <exec_depend>rospy</exec_depend>
  <export>
    <!-- Other tools can request additional information be placed here -->
  </export>
</package>
""", ("setup.py", "CMakeLists.txt")),
}


@pytest.mark.parametrize("name", sorted(MANIFESTS))
def test_real_manifest_forms_give_nothing(tmp_path: Path, name: str) -> None:
    xml, extra = MANIFESTS[name]
    files = {"package.xml": xml, **{f: SETUP_PY if f == "setup.py" else CMAKE for f in extra}}
    package = make_package(tmp_path / "demo_pkg", files)
    assert [(f.code, f.span.line, f.message) for f in findings(package, *MAN_RULES)] == []


def test_ros2_pkg_create_defaults_are_only_placeholders(tmp_path: Path) -> None:
    xml = ROS2_PKG_CREATE.format(description="TODO: Package description", email="user@todo.todo",
                                 user="user", license="TODO: License declaration")
    package = make_package(tmp_path / "demo_pkg", {"package.xml": xml, "setup.py": SETUP_PY})
    assert [(f.code, f.span.line) for f in findings(package, *MAN_RULES)] == [
        ("MAN017", 6), ("MAN017", 7), ("MAN017", 8)]


@pytest.mark.parametrize("root", sorted(p.parent for p in REFERENCE.glob("*/package.xml")),
                         ids=lambda p: p.name)
def test_reference_packages_have_no_manifest_errors_or_warnings(root: Path) -> None:
    found = findings(load_package(root), *MAN_RULES)
    assert [(f.code, f.span.line, f.message) for f in found
            if f.severity is not Severity.INFO] == []
