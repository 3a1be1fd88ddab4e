"""Seeded package.xml mistakes (MAN, and SYN for XML that is not well-formed)."""

from __future__ import annotations

from pathlib import Path

from tests.lint.seeded import case, edit

XML = "package.xml"
LICENSE = "  <license>Apache-2.0</license>\n"
EXPORT = "  <export>\n    <build_type>ament_python</build_type>\n  </export>\n"


def _add(root: Path, lines: str) -> None:
    """Insert dependency lines after the last ``<exec_depend>``."""
    edit(root, XML, "  <exec_depend>launch_ros</exec_depend>\n",
         f"  <exec_depend>launch_ros</exec_depend>\n{lines}")


@case("MAN001", XML, "<name>Base_Pkg</name>")
def uppercase_name(root: Path) -> None:
    edit(root, XML, "<name>base_pkg</name>", "<name>Base_Pkg</name>")


@case("MAN001", XML, "<name>base-pkg</name>")
def dashed_name(root: Path) -> None:
    edit(root, XML, "<name>base_pkg</name>", "<name>base-pkg</name>")


@case("MAN002", XML, "<version>1.0</version>")
def two_part_version(root: Path) -> None:
    edit(root, XML, "<version>0.0.0</version>", "<version>1.0</version>")
    edit(root, "setup.py", "version='0.0.0'", "version='1.0'")


@case("MAN002", XML, "<version>0.1.0-beta</version>")
def version_with_suffix(root: Path) -> None:
    edit(root, XML, "<version>0.0.0</version>", "<version>0.1.0-beta</version>")


@case("MAN003", XML, "<package format")
def license_missing(root: Path) -> None:
    edit(root, XML, LICENSE, "")


@case("MAN003", XML, "<package format")
def description_missing(root: Path) -> None:
    edit(root, XML, "  <description>The base_pkg ROS 2 Python package.</description>\n", "")


@case("MAN007", XML, "<maintainer>Jane Doe</maintainer>")
def maintainer_email_missing(root: Path) -> None:
    edit(root, XML, '<maintainer email="jane@example.com">', "<maintainer>")


@case("MAN007", XML, "<maintainer email=")
def maintainer_email_malformed(root: Path) -> None:
    edit(root, XML, 'email="jane@example.com"', 'email="jane at example.com"')


@case("MAN005", XML, "<exec_depends>numpy_helpers</exec_depends>")
def misspelled_dependency_tag(root: Path) -> None:
    _add(root, "  <exec_depends>numpy_helpers</exec_depends>\n")


@case("MAN005", XML, "<dependency>")
def made_up_tag(root: Path) -> None:
    _add(root, "  <dependency>geometry_msgs</dependency>\n")


@case("MAN004", XML, "<description>")
def description_after_maintainer(root: Path) -> None:
    description = "  <description>The base_pkg ROS 2 Python package.</description>\n"
    edit(root, XML, description, "")
    edit(root, XML, LICENSE, LICENSE + description)


@case("MAN004", XML, "<exec_depend>rclpy</exec_depend>")
def dependency_after_export(root: Path) -> None:
    edit(root, XML, "</export>\n", "</export>\n  <exec_depend>rclpy</exec_depend>\n")


@case("MAN006", XML, "<run_depend>")
def run_depend_in_format_3(root: Path) -> None:
    _add(root, "  <run_depend>sensor_msgs</run_depend>\n")


@case("MAN018", XML, "<buildtool_depend>ament_python</buildtool_depend>")
def buildtool_depend_ament_python(root: Path) -> None:
    edit(root, XML, "  <depend>rclpy</depend>",
         "  <buildtool_depend>ament_python</buildtool_depend>\n\n  <depend>rclpy</depend>")


@case("MAN018", XML, "python-opencv")
def python_opencv_key(root: Path) -> None:
    _add(root, "  <exec_depend>python-opencv</exec_depend>\n")


@case("MAN018", XML, "opencv-python")
def pip_name_as_key(root: Path) -> None:
    _add(root, "  <exec_depend>opencv-python</exec_depend>\n")


@case("MAN018", XML, "<exec_depend>numpy</exec_depend>")
def import_name_as_key(root: Path) -> None:
    _add(root, "  <exec_depend>numpy</exec_depend>\n")


@case("MAN018", XML, "<exec_depend>rospy</exec_depend>")
def ros1_key(root: Path) -> None:
    _add(root, "  <exec_depend>rospy</exec_depend>\n")


@case("MAN017", XML, "TODO: Package description")
def template_description(root: Path) -> None:
    edit(root, XML, "The base_pkg ROS 2 Python package.", "TODO: Package description")


@case("MAN017", XML, "TODO: License declaration")
def template_license(root: Path) -> None:
    edit(root, XML, "<license>Apache-2.0</license>",
         "<license>TODO: License declaration</license>")


@case("MAN015", XML, "<package format")
def build_type_missing(root: Path) -> None:
    edit(root, XML, EXPORT, "")


@case("MAN016", XML, "<build_type>ament_cmake</build_type>")
def build_type_ament_cmake(root: Path) -> None:
    edit(root, XML, "ament_python</build_type>", "ament_cmake</build_type>")


@case("MAN005", XML, "<build_type>ament_python</build_type>")
def build_type_outside_export(root: Path) -> None:
    edit(root, XML, EXPORT, "  <build_type>ament_python</build_type>\n")


@case("MAN013", XML, "<!-- again -->")
def duplicate_dependency(root: Path) -> None:
    _add(root, "  <exec_depend>launch_ros</exec_depend>  <!-- again -->\n")


@case("MAN012", XML, "<exec_depend>rclpy</exec_depend>")
def depend_repeated_as_exec_depend(root: Path) -> None:
    _add(root, "  <exec_depend>rclpy</exec_depend>\n")


@case("MAN014", XML, "<exec_depend>base_pkg</exec_depend>")
def self_dependency(root: Path) -> None:
    _add(root, "  <exec_depend>base_pkg</exec_depend>\n")


@case("MAN010", XML, '<package format="4">')
def unknown_format(root: Path) -> None:
    edit(root, XML, '<package format="3">', '<package format="4">')


@case("MAN011", XML, "<version>0.0.1</version>")
def version_twice(root: Path) -> None:
    edit(root, XML, "<version>0.0.0</version>", "<version>0.0.0</version>\n"
         "  <version>0.0.1</version>")


@case("MAN008", XML, '<url type="github">')
def url_type_unknown(root: Path) -> None:
    edit(root, XML, LICENSE, LICENSE + '  <url type="github">https://github.com/x/y</url>\n')


@case("MAN006", XML, "<depend>rclpy</depend>")
def format_attribute_left_out(root: Path) -> None:
    edit(root, XML, '<package format="3">', "<package>")


@case("MAN018", XML, "<test_depend>pytest</test_depend>")
def pip_name_as_test_depend(root: Path) -> None:
    edit(root, XML, "<test_depend>python3-pytest</test_depend>",
         "<test_depend>pytest</test_depend>")


@case("MAN024", "base_pkg/talker.py", "from std_msgs.msg import String")  # holds the DEP001
def dependency_inside_export(root: Path) -> None:
    edit(root, XML, "  <depend>std_msgs</depend>\n", "")
    edit(root, XML, "  <export>\n", "  <export>\n    <depend>std_msgs</depend>\n")


@case("MAN003", XML, "<description>")
def description_empty(root: Path) -> None:
    edit(root, XML, "The base_pkg ROS 2 Python package.", "")


@case("MAN007", XML, 'email=""')
def maintainer_email_empty(root: Path) -> None:
    edit(root, XML, 'email="jane@example.com"', 'email=""')


@case("MAN020", "setup.py", "'resource/' + package_name")
def package_xml_missing(root: Path) -> None:
    (root / XML).unlink()


@case("SYN001", XML, "<name>base_pkg</nam>")
def mismatched_tag(root: Path) -> None:
    edit(root, XML, "<name>base_pkg</name>", "<name>base_pkg</nam>")


@case("SYN001", XML)
def unclosed_package(root: Path) -> None:
    edit(root, XML, "</package>", "")


@case("MAN009", XML, '<depend version-gte="1.0.0"')
def misspelled_version_attribute(root: Path) -> None:
    edit(root, XML, "<depend>rclpy</depend>", '<depend version-gte="1.0.0">rclpy</depend>')


@case("MAN018", XML, "<buildtool_depend>catkin</buildtool_depend>")
def ros1_buildtool(root: Path) -> None:
    edit(root, XML, "  <depend>rclpy</depend>",
         "  <buildtool_depend>catkin</buildtool_depend>\n\n  <depend>rclpy</depend>")


@case("MAN021", XML, "<depend>std_msg</depend>")
def message_package_misspelled(root: Path) -> None:
    edit(root, XML, "<depend>std_msgs</depend>", "<depend>std_msg</depend>")


@case("MAN021", XML, "<exec_depend>launch_ro</exec_depend>")
def launch_package_misspelled(root: Path) -> None:
    edit(root, XML, "<exec_depend>launch_ros</exec_depend>",
         "<exec_depend>launch_ro</exec_depend>")


@case("MAN025", XML, "package_format3.xsd")
def format_lowered_below_the_schema_line(root: Path) -> None:
    edit(root, XML, '<package format="3">', '<package format="2">')
