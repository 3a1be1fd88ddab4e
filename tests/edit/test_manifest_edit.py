"""package.xml edits: schema order, the file's layout, sorted groups, clean removal."""

from __future__ import annotations

import textwrap

import pytest
from lxml import etree

from pkgtool.edit import EditError, apply_edits
from pkgtool.edit.manifest import ManifestDoc
from pkgtool.edit.source import Source

HEAD = """<?xml version="1.0"?>
<package format="3">
  <name>demo</name>
  <version>0.1.0</version>
  <description>Demo.</description>
  <maintainer email="a@b.org">A</maintainer>
  <license>MIT</license>
"""


def _add(text: str, tag: str, name: str, **attributes: str) -> str:
    text = textwrap.dedent(text)
    doc = ManifestDoc(Source("package.xml", text))
    return apply_edits(text, doc.add(tag, name, attributes or None))


def test_into_a_sorted_group_at_its_place() -> None:
    text = HEAD + "  <depend>rclpy</depend>\n  <depend>std_msgs</depend>\n</package>\n"
    assert _add(text, "depend", "sensor_msgs") == HEAD + (
        "  <depend>rclpy</depend>\n  <depend>sensor_msgs</depend>\n"
        "  <depend>std_msgs</depend>\n</package>\n")
    assert _add(text, "depend", "ament_index_python").startswith(
        HEAD + "  <depend>ament_index_python</depend>\n  <depend>rclpy</depend>\n")


def test_an_unsorted_group_gets_the_new_element_at_its_end() -> None:
    text = HEAD + "  <depend>std_msgs</depend>\n  <depend>rclpy</depend>\n</package>\n"
    assert _add(text, "depend", "a_pkg") == HEAD + (
        "  <depend>std_msgs</depend>\n  <depend>rclpy</depend>\n  <depend>a_pkg</depend>\n"
        "</package>\n")


def test_a_new_group_follows_the_blank_line_layout_and_schema_order() -> None:
    text = (HEAD + "\n  <depend>rclpy</depend>\n\n  <test_depend>python3-pytest</test_depend>\n"
            "\n  <export>\n    <build_type>ament_python</build_type>\n  </export>\n</package>\n")
    assert _add(text, "exec_depend", "python3-numpy") == text.replace(
        "  <depend>rclpy</depend>\n", "  <depend>rclpy</depend>\n\n"
        "  <exec_depend>python3-numpy</exec_depend>\n")
    assert _add(text, "buildtool_depend", "ament_python") == text.replace(
        "  <license>MIT</license>\n", "  <license>MIT</license>\n\n"
        "  <buildtool_depend>ament_python</buildtool_depend>\n")


def test_tabs_crlf_attributes_and_a_trailing_comment_are_kept() -> None:
    text = HEAD.replace("  ", "\t").replace("\n", "\r\n") + (
        "\t<exec_depend>rclpy</exec_depend> <!-- the client library -->\r\n</package>\r\n")
    result = _add(text, "exec_depend", "std_msgs", condition="$ROS_VERSION == 2")
    assert result == text.replace("library -->\r\n", "library -->\r\n\t<exec_depend "
                                  'condition="$ROS_VERSION == 2">std_msgs</exec_depend>\r\n')


def test_adding_what_is_there_changes_nothing() -> None:
    text = HEAD + ("  <exec_depend>\n    rclpy\n  </exec_depend>\n"
                   "  <depend condition='$X &gt;= 2'>a&amp;b</depend>\n</package>\n")
    doc = ManifestDoc(Source("package.xml", text))
    assert doc.add("exec_depend", "rclpy") == []
    assert doc.add("depend", "a&b", {"condition": "$X >= 2"}) == []


def test_format_one_and_unknown_tags() -> None:
    text = HEAD.replace(' format="3"', "") + "  <run_depend>rclpy</run_depend>\n</package>\n"
    assert "<run_depend>std_msgs</run_depend>" in _add(text, "run_depend", "std_msgs")
    with pytest.raises(EditError, match="format 1"):
        _add(text, "exec_depend", "std_msgs")


def test_special_characters_are_escaped_and_read_back() -> None:
    text = HEAD + "</package>\n"
    result = _add(text, "url", "https://example.com/?a=1&b=<2>")
    root = etree.fromstring(result.encode())
    assert root.findtext("url") == "https://example.com/?a=1&b=<2>"


@pytest.mark.parametrize(("body", "expected"), [
    ("  <depend>a</depend>\n  <depend>b</depend>\n", "  <depend>b</depend>\n"),
    ("\n  <depend>a</depend>\n\n  <export/>\n", "\n  <export/>\n"),
    ("  <depend>a</depend><depend>b</depend>\n", "  <depend>b</depend>\n"),
])
def test_removal_takes_the_line_and_one_surrounding_blank(body: str, expected: str) -> None:
    text = HEAD + body + "</package>\n"
    doc = ManifestDoc(Source("package.xml", text))
    assert apply_edits(text, [doc.remove(doc.find("depend", "a")[0])]) == \
        HEAD + expected + "</package>\n"


def test_a_file_that_is_not_a_manifest_is_refused() -> None:
    with pytest.raises(EditError, match="well-formed"):
        ManifestDoc(Source("package.xml", "<launch/>\n"))
