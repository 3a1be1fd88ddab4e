"""MAN004's fix: package.xml's children in the schema's order, each with its own comments."""

from __future__ import annotations

from pathlib import Path

from pkgtool.commands.lint import LintOptions, LintResult, run
from tests.helpers import correct_package_files, write_tree

HEAD = ('<?xml version="1.0"?>\n<?xml-model href="http://download.ros.org/schema/'
        'package_format3.xsd" schematypens="http://www.w3.org/2001/XMLSchema"?>\n'
        '<package format="3">\n')


def _package(tmp_path: Path, children: str) -> Path:
    files = correct_package_files("pkg")
    files["package.xml"] = HEAD + children + "</package>\n"
    root = tmp_path / "pkg"
    write_tree(root, files)
    return root


def _fix(root: Path) -> LintResult:
    return run([str(root)], options=LintOptions(isolated=True, fix=True, select=("MAN004",)))


OUT_OF_ORDER = """\
  <name>pkg</name>
  <version>0.1.0</version>
  <description>Demo</description>
  <!-- who to ask -->
  <license>MIT</license>  <!-- the code's license -->
  <maintainer email="ada@example.com">Ada</maintainer>

  <exec_depend>rclpy</exec_depend>
  <export>
    <build_type>ament_python</build_type>
  </export>
  <test_depend>python3-pytest</test_depend>
  <url>https://example.com</url>
"""

IN_ORDER = """\
  <name>pkg</name>
  <version>0.1.0</version>
  <description>Demo</description>
  <maintainer email="ada@example.com">Ada</maintainer>
  <!-- who to ask -->
  <license>MIT</license>  <!-- the code's license -->
  <url>https://example.com</url>

  <exec_depend>rclpy</exec_depend>
  <test_depend>python3-pytest</test_depend>
  <export>
    <build_type>ament_python</build_type>
  </export>
"""


def test_children_move_into_order_with_their_comments(tmp_path: Path) -> None:
    root = _package(tmp_path, OUT_OF_ORDER)
    result = _fix(root)
    assert not [f for f in result.findings if f.code == "MAN004"], result.findings
    assert (root / "package.xml").read_text() == HEAD + IN_ORDER + "</package>\n"
    again = _fix(root)
    assert not again.fixed and (root / "package.xml").read_text() == HEAD + IN_ORDER + \
        "</package>\n"


def test_elements_sharing_a_line_are_refused_with_the_reason(tmp_path: Path) -> None:
    shared = OUT_OF_ORDER.replace("  <exec_depend>rclpy</exec_depend>\n",
                                  "  <exec_depend>rclpy</exec_depend><url>x</url>\n")
    root = _package(tmp_path, shared)
    before = (root / "package.xml").read_text()
    result = _fix(root)
    assert (root / "package.xml").read_text() == before and not result.fixed
    assert any("lines of its own" in note for note in result.notes), result.notes
