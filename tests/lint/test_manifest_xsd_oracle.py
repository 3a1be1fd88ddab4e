"""pkgtool's schema rules (MAN001-MAN011) give an error exactly when the official XSD rejects.

The REP 127/140/149 XSDs in ``tests/data/rep-xsd`` (a copy, see its README.md) are the
oracle, validated with lxml offline (``package_common.xsd`` is included by a relative path).
pkgtool never reads them. Deliberate deviations are listed in :data:`DEVIATIONS` with the
reason and checked too.
"""

from __future__ import annotations

import functools
from pathlib import Path

import pytest
from lxml import etree

from tests.helpers import findings, make_package

XSD_DIR = Path(__file__).resolve().parents[1] / "data" / "rep-xsd"
SCHEMA_RULES = tuple(f"MAN{n:03d}" for n in range(1, 12))

pytestmark = pytest.mark.oracle

HEAD = """<name>demo_pkg</name>
  <version>0.1.0</version>
  <description>A demo package</description>
  <maintainer email="ada@example.com">Ada Lovelace</maintainer>
  <license>Apache-2.0</license>"""
EXPORT = "<export><build_type>ament_python</build_type></export>"


def doc(body: str = EXPORT, *, fmt: str | None = "3", head: str = HEAD, attrs: str = "") -> str:
    """A package.xml with the standard head (override ``head`` to break it), naming the
    schema of its format as ``ros2 pkg create`` writes (MAN004 checks only such manifests)."""
    format_attr = f' format="{fmt}"' if fmt is not None else ""
    schema = fmt if fmt in ("1", "2", "3") else "1"
    return (f'<?xml version="1.0"?>\n<?xml-model href="http://download.ros.org/schema/'
            f'package_format{schema}.xsd" schematypens="http://www.w3.org/2001/XMLSchema"?>\n'
            f'<package{format_attr}{attrs}>\n  {head}\n  {body}\n</package>\n')


def head(**replace: str) -> str:
    """HEAD with some lines replaced, keyed by tag (``''`` drops the element)."""
    lines = HEAD.split("\n  ")
    tags = [line[1:line.index(">")].split()[0] for line in lines]
    return "\n  ".join(replace.get(tag, line) for tag, line in zip(tags, lines)
                       if replace.get(tag, line))


EVERY_ELEMENT = """<url type="website">https://example.com/demo_pkg</url>
  <url type="repository">https://github.com/ada/demo_pkg.git</url>
  <url type="bugtracker">https://github.com/ada/demo_pkg/issues?q=is%3Aopen#top</url>
  <url>relative/docs.html</url>
  <author email="grace@example.com">Grace Hopper</author>
  <author>Alan Turing</author>
  <buildtool_depend>ament_cmake_python</buildtool_depend>
  <buildtool_export_depend>ament_cmake_python</buildtool_export_depend>
  <build_depend version_gte="1.0">builtin_interfaces</build_depend>
  <build_export_depend>builtin_interfaces</build_export_depend>
  <depend version_gte="7" version_lt="8.0.0">rclpy</depend>
  <exec_depend version_eq="1.2.3">std_msgs</exec_depend>
  <doc_depend>python3-sphinx</doc_depend>
  <test_depend version_lte="9">python3-pytest</test_depend>
  <conflict version_gt="0.0.1">old_demo_pkg</conflict>
  <replace>older_demo_pkg</replace>"""

VALID = {
    "ros2_pkg_create_format3": doc("""<test_depend>ament_copyright</test_depend>
  <test_depend>ament_flake8</test_depend>
  <test_depend>ament_pep257</test_depend>
  <test_depend>python3-pytest</test_depend>
  """ + EXPORT),
    "format2_authors_exec_depends": doc("""<author>Mikael</author>
  <author email="esteve@example.org">Esteve</author>
  <exec_depend>example_interfaces</exec_depend>
  <exec_depend>rclpy</exec_depend>
  <test_depend>python3-pytest</test_depend>
  """ + EXPORT, fmt="2"),
    "format3_every_element": doc(EVERY_ELEMENT + """
  <group_depend>rosidl_interface_packages</group_depend>
  <member_of_group>my_tools</member_of_group>
  <export>
    <build_type>ament_python</build_type>
    <architecture_independent/>
    <rosdoc config="rosdoc.yaml"/>
    <any_tool xmlns="http://example.com/tool" flag="1"><nested>x</nested></any_tool>
  </export>"""),
    "format2_every_element": doc(EVERY_ELEMENT + "\n  " + EXPORT, fmt="2"),
    "format1_every_element": doc("""<url>https://example.com</url>
  <author>Grace</author>
  <buildtool_depend>catkin</buildtool_depend>
  <build_depend version_gte="1.0">roscpp</build_depend>
  <run_depend>roscpp</run_depend>
  <test_depend>rosunit</test_depend>
  <conflict>x_old</conflict>
  <replace>x_older</replace>
  <export><metapackage/></export>""", fmt="1"),
    "format1_without_format_attribute": doc("<run_depend>rospy</run_depend>", fmt=None),
    "format3_conditions": doc("""<depend condition="$ROS_VERSION == 2">rclpy</depend>
  <depend condition="$ROS_VERSION == 1">rospy</depend>
  <exec_depend condition="$ROS_DISTRO != 'humble' and $X == &quot;y&quot;">std_msgs</exec_depend>
  <exec_depend condition="($ROS_VERSION >= 2) or ($ROS_VERSION &lt; 1)">nav_msgs</exec_depend>
  <group_depend condition="$ROS_VERSION == 2">my_plugins</group_depend>
  <member_of_group condition="$ROS_VERSION != 1">rosidl_interface_packages</member_of_group>
  <export>
    <build_type condition="$ROS_VERSION == 1">catkin</build_type>
    <build_type condition="$ROS_VERSION == 2">ament_python</build_type>
  </export>"""),
    "xsi_schema_location": doc(attrs=' xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"'
                               ' xsi:noNamespaceSchemaLocation="http://download.ros.org/schema/'
                               'package_format3.xsd"'),
    "description_with_xhtml": doc(head=head(
        description='<description>Drives <b>the</b> robot. <a href="x">Docs</a></description>')),
    "several_maintainers_and_licenses": doc(head=head(license="""<maintainer
    email="grace.h+ros@mail.example.co.uk">Grace</maintainer>
  <license>Apache-2.0</license>
  <license>BSD-3-Clause</license>
  <license>Apache License 2.0</license>""")),
    "license_file_format3": doc(head=head(license='<license file="LICENSE">MIT</license>')),
    "comments_and_processing_instructions": doc(
        "<!-- deps --><exec_depend>rclpy</exec_depend><?tool x?>\n  " + EXPORT,
        head=head(name="<name>demo_pkg<!-- the name --></name>")),
    "whitespace_around_values": doc(head=head(
        name="<name>\n    demo_pkg\n  </name>", version="<version> 0.1.0 </version>")),
    "empty_url_and_dependency": doc("<url></url>\n  <depend></depend>\n  " + EXPORT),
    "single_letter_name_zero_version": doc(head=head(name="<name>a</name>",
                                                     version="<version>0.0.0</version>")),
    "url_type_with_spaces": doc('<url type=" website ">https://example.com</url>\n  ' + EXPORT),
    "format2_metapackage": doc("""<buildtool_depend>ament_cmake</buildtool_depend>
  <exec_depend>demo_a</exec_depend>
  <exec_depend>demo_b</exec_depend>
  <export><build_type>ament_cmake</build_type><metapackage/></export>""", fmt="2"),
}

INVALID = {
    "name_uppercase": doc(head=head(name="<name>Demo_pkg</name>")),
    "name_dash": doc(head=head(name="<name>demo-pkg</name>")),
    "name_double_underscore": doc(head=head(name="<name>demo__pkg</name>")),
    "name_trailing_underscore": doc(head=head(name="<name>demo_</name>")),
    "name_leading_digit": doc(head=head(name="<name>3d_demo</name>"), fmt="2"),
    "name_inner_space": doc(head=head(name="<name>demo pkg</name>")),
    "name_empty": doc(head=head(name="<name></name>")),
    "version_two_parts": doc(head=head(version="<version>1.0</version>")),
    "version_leading_zero": doc(head=head(version="<version>1.0.01</version>"), fmt="2"),
    "version_suffix": doc(head=head(version="<version>1.0.0-rc1</version>")),
    "version_empty": doc(head=head(version="<version></version>")),
    "missing_name": doc(head=head(name="")),
    "missing_version": doc(head=head(version=""), fmt="2"),
    "missing_description": doc(head=head(description="")),
    "missing_maintainer": doc(head=head(maintainer="")),
    "missing_license": doc(head=head(license=""), fmt="1"),
    "order_license_before_maintainer": doc(head=head(
        maintainer="<license>MIT</license>",
        license='<maintainer email="ada@example.com">Ada</maintainer>')),
    "order_description_before_version": doc(head=head(
        version="<description>d</description>", description="<version>0.1.0</version>")),
    "order_author_before_url": doc("<author>Grace</author>\n  <url>https://x.org</url>"),
    "order_depend_before_author": doc("<depend>rclpy</depend>\n  <author>Grace</author>",
                                      fmt="2"),
    "order_export_before_depend": doc(EXPORT + "\n  <exec_depend>rclpy</exec_depend>"),
    "order_member_before_group": doc("<member_of_group>a</member_of_group>\n"
                                     "  <group_depend>b</group_depend>"),
    "order_group_before_depend": doc("<group_depend>b</group_depend>\n"
                                     "  <exec_depend>rclpy</exec_depend>"),
    "duplicate_name": doc(head=HEAD.replace("</name>", "</name>\n  <name>again</name>")),
    "duplicate_export": doc(EXPORT + "\n  <export><metapackage/></export>"),
    "unknown_element": doc("<exec_depends>rclpy</exec_depends>\n  " + EXPORT),
    "unknown_element_build_type": doc("<build_type>ament_python</build_type>"),
    "nested_element_in_maintainer": doc(head=head(
        maintainer='<maintainer email="a@b.co">Ada <b>L</b></maintainer>')),
    "nested_element_in_depend": doc("<depend><name>rclpy</name></depend>"),
    "stray_text": doc(head=HEAD + ">"),
    "stray_text_after_comment": doc("<!-- c --> oops\n  " + EXPORT),
    "root_not_package": '<?xml version="1.0"?>\n<manifest format="3"><name>x</name></manifest>\n',
    "run_depend_format2": doc("<run_depend>rclpy</run_depend>", fmt="2"),
    "run_depend_format3": doc("<run_depend>rclpy</run_depend>"),
    "exec_depend_format1": doc("<exec_depend>rospy</exec_depend>", fmt="1"),
    "depend_without_format": doc("<depend>rclpy</depend>", fmt=None),
    "group_depend_format2": doc("<group_depend>g</group_depend>", fmt="2"),
    "member_of_group_format2": doc("<member_of_group>g</member_of_group>", fmt="2"),
    "maintainer_without_email": doc(head=head(maintainer="<maintainer>Ada</maintainer>")),
    "maintainer_bad_email": doc(head=head(
        maintainer='<maintainer email="ada(at)example.com">Ada</maintainer>')),
    "maintainer_email_without_tld": doc(head=head(
        maintainer='<maintainer email="ada@localhost">Ada</maintainer>')),
    "author_bad_email": doc('<author email="grace@">Grace</author>'),
    "url_bad_type": doc('<url type="source">https://github.com/a/b</url>'),
    "url_bad_percent": doc("<url>https://example.com/100%</url>"),
    "url_scp_like": doc("<url>git@github.com:ada/demo_pkg.git</url>"),
    "condition_format2": doc('<exec_depend condition="$ROS_VERSION == 2">rclpy</exec_depend>',
                             fmt="2"),
    "condition_bad_character": doc('<exec_depend condition="$X == 1.5">rclpy</exec_depend>'),
    "group_condition_with_quote": doc(
        "<group_depend condition=\"$ROS_DISTRO == 'jazzy'\">g</group_depend>"),
    "version_attribute_bad_value": doc('<depend version_gte="1.0.0-1">rclpy</depend>'),
    "version_attribute_leading_zero": doc('<depend version_lt="01">rclpy</depend>', fmt="2"),
    "version_attribute_misspelt": doc('<depend version_ge="1.0">rclpy</depend>'),
    "attribute_on_name": doc(head=head(name='<name lang="en">demo_pkg</name>')),
    "attribute_on_package": doc(attrs=' version="1"'),
    "attribute_on_export": doc('<export foo="1"><build_type>ament_python</build_type></export>'),
    "xml_lang_on_description": doc(head=head(
        description='<description xml:lang="en">A demo</description>')),
    "license_file_format2": doc(head=head(license='<license file="LICENSE">MIT</license>'),
                                fmt="2"),
    "compatibility_format2": doc(head=head(
        version='<version compatibility="0.1.0">0.1.0</version>'), fmt="2"),
    "format_4": doc(fmt="4"),
    "format_3_0": doc(fmt="3.0"),
    "format_with_space": doc(fmt=" 3"),
    "format_empty": doc(fmt=""),
    "format_leading_zero": doc(fmt="03"),
}

DEVIATIONS = {
    # name: (the XSD accepts it, why pkgtool decides otherwise)
    "version_letter_separators": (doc(head=head(version="<version>1a2b3</version>")), True,
                                  "the XSD pattern writes an unescaped `.`; REP 127/140/149 and "
                                  "catkin_pkg require dots"),
    "version_limit_dash": (doc('<depend version_gte="1-2">rclpy</depend>'), True,
                           "same unescaped `.` in VersionLimitType"),
    "email_with_surrounding_spaces": (doc(head=head(
        maintainer='<maintainer email=" ada@example.com ">Ada</maintainer>')), True,
        "xs:token trims it, catkin_pkg does not and rejects the manifest"),
    "empty_description": (doc(head=head(description="<description> </description>")), True,
                          "catkin_pkg rejects an empty description"),
    "empty_license": (doc(head=head(license="<license></license>")), True,
                      "catkin_pkg rejects an empty license"),
    "compatibility_format3": (doc(head=head(
        version='<version compatibility="0.1.0">0.1.0</version>')), False,
        "REP 149 defines `compatibility`; the XSD declares its type but never uses it"),
    "default_namespace": (doc(attrs=' xmlns="http://example.com/ns"'), False,
                          "pkgtool reads local names; namespaced package.xml files are not "
                          "seen in practice"),
}


@functools.cache
def _schemas() -> tuple[etree.XMLSchema, ...]:
    parser = etree.XMLParser(no_network=True, resolve_entities=False)
    return tuple(etree.XMLSchema(etree.parse(str(XSD_DIR / f"package_format{fmt}.xsd"), parser))
                 for fmt in (1, 2, 3))


def xsd_accepts(xml: str) -> bool:
    """The official verdict: each XSD fixes its ``format`` value, so at most one can accept."""
    root = etree.fromstring(xml.encode())
    return any(schema.validate(root) for schema in _schemas())


def pkgtool_accepts(tmp_path: Path, xml: str) -> bool:
    package = make_package(tmp_path / "demo_pkg", {"package.xml": xml})
    assert package.manifest is not None, package.problems
    return not findings(package, *SCHEMA_RULES)


def test_corpus_is_varied() -> None:
    documents = {**VALID, **INVALID}
    assert len(documents) >= 40
    for fmt in ('format="2"', 'format="3"'):
        assert any(fmt in xml for xml in VALID.values())
        assert sum(fmt in xml for xml in INVALID.values()) >= 5


@pytest.mark.parametrize("name", sorted(VALID))
def test_valid_documents(tmp_path: Path, name: str) -> None:
    assert xsd_accepts(VALID[name]), "the corpus entry itself is wrong"
    assert pkgtool_accepts(tmp_path, VALID[name])


@pytest.mark.parametrize("name", sorted(INVALID))
def test_invalid_documents(tmp_path: Path, name: str) -> None:
    assert not xsd_accepts(INVALID[name]), "the corpus entry itself is wrong"
    assert not pkgtool_accepts(tmp_path, INVALID[name])


@pytest.mark.parametrize("name", sorted(DEVIATIONS))
def test_documented_deviations(tmp_path: Path, name: str) -> None:
    xml, xsd_verdict, _reason = DEVIATIONS[name]
    assert xsd_accepts(xml) is xsd_verdict
    assert pkgtool_accepts(tmp_path, xml) is not xsd_verdict
