"""Rules whose docs say "catkin_pkg rejects the manifest" fire exactly when catkin_pkg does.

catkin_pkg is what colcon parses package.xml with: when it raises, colcon does not see a ROS
package. Severity of these rules rests on this behaviour, so it is checked against the real
library (schema-only defects such as element order are the XSD oracle's business).
"""

from __future__ import annotations

from pathlib import Path

import catkin_pkg.package as catkin_package  # the test extra declares catkin-pkg
import pytest

from tests.helpers import findings, make_package
from tests.lint.test_manifest_xsd_oracle import EXPORT, doc, head

pytestmark = pytest.mark.oracle

CATKIN_RULES = ("MAN003", "MAN005", "MAN006", "MAN007", "MAN011", "MAN012", "MAN014")

REJECTED = {
    "depend_and_exec_depend": ("MAN012", doc("<depend>rclpy</depend>\n"
                                             "  <exec_depend>rclpy</exec_depend>")),
    "build_depend_before_depend": ("MAN012", doc("<build_depend>a</build_depend>\n"
                                                 "  <depend>a</depend>", fmt="2")),
    "depend_twice": ("MAN012", doc("<depend>rclpy</depend>\n  <depend>rclpy</depend>")),
    "format1_test_depend_repeats_run_depend": ("MAN012", doc(
        "<run_depend>rospy</run_depend>\n  <test_depend>rospy</test_depend>", fmt=None)),
    "self_exec_depend": ("MAN014", doc("<exec_depend>demo_pkg</exec_depend>")),
    "self_test_depend": ("MAN014", doc("<test_depend>demo_pkg</test_depend>", fmt="2")),
    "group_depend_on_own_group": ("MAN014", doc("<group_depend>g</group_depend>\n"
                                                "  <member_of_group>g</member_of_group>")),
    "empty_description": ("MAN003", doc(head=head(description="<description/>"))),
    "empty_license": ("MAN003", doc(head=head(license="<license> </license>"))),
    "missing_maintainer": ("MAN003", doc(head=head(maintainer=""))),
    "maintainer_without_email": ("MAN007", doc(head=head(
        maintainer="<maintainer>Ada</maintainer>"))),
    "email_with_spaces": ("MAN007", doc(head=head(
        maintainer='<maintainer email="ada@example.com ">Ada</maintainer>'))),
    "two_exports": ("MAN011", doc(EXPORT + "\n  <export/>")),
    "two_versions": ("MAN011", doc(head=head(
        version="<version>1.0.0</version>\n  <version>1.0.1</version>"))),
    "run_depend_format2": ("MAN006", doc("<run_depend>rclpy</run_depend>", fmt="2")),
    "exec_depend_format1": ("MAN006", doc("<exec_depend>rospy</exec_depend>", fmt="1")),
    "unknown_tag": ("MAN005", doc("<exec_depends>rclpy</exec_depends>")),
    "element_in_depend": ("MAN005", doc("<depend>rclpy<b/></depend>")),
}

ACCEPTED = {
    "typical": doc(f"<depend>rclpy</depend>\n  <test_depend>x</test_depend>\n  {EXPORT}"),
    "depend_and_exec_depend_with_other_version": doc(
        '<depend>rclpy</depend>\n  <exec_depend version_gte="7">rclpy</exec_depend>'),
    "depend_and_exec_depend_with_other_condition": doc(
        '<depend condition="$ROS_VERSION == 2">a</depend>\n'
        '  <exec_depend condition="$ROS_VERSION == 1">a</exec_depend>'),
    "depend_and_test_depend": doc("<depend>rclpy</depend>\n  <test_depend>rclpy</test_depend>"),
    "exec_depend_twice": doc("<exec_depend>rclpy</exec_depend>\n"
                             "  <exec_depend>rclpy</exec_depend>"),
    "dependency_on_similar_name": doc("<exec_depend>demo_pkg_msgs</exec_depend>"),
    "out_of_order": doc("<author>Grace</author>\n  <url>https://example.com</url>"),
}


def _catkin_rejects(xml: str) -> bool:
    try:
        catkin_package.parse_package_string(xml, warnings=[])
    except catkin_package.InvalidPackage:
        return True
    return False


def _codes(tmp_path: Path, xml: str) -> set[str]:
    package = make_package(tmp_path / "demo_pkg", {"package.xml": xml})
    return {f.code for f in findings(package, *CATKIN_RULES)}


@pytest.mark.parametrize("name", sorted(REJECTED))
def test_catkin_rejects_and_the_rule_fires(tmp_path: Path, name: str) -> None:
    code, xml = REJECTED[name]
    assert _catkin_rejects(xml)
    assert _codes(tmp_path, xml) == {code}


@pytest.mark.parametrize("name", sorted(ACCEPTED))
def test_catkin_accepts_and_no_catkin_rule_fires(tmp_path: Path, name: str) -> None:
    assert not _catkin_rejects(ACCEPTED[name])
    assert _codes(tmp_path, ACCEPTED[name]) == set()
