"""Reading .msg, .srv and .action files as rosidl generates their Python classes."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from pkgtool.cache.serial import index_entry, index_record
from pkgtool.knowledge.tables import read
from pkgtool.model.context import read_workspace_package
from pkgtool.knowledge.interface_definitions import definitions


def _installed_interface_files() -> list[Path]:
    """The interface files the ROS wheels of this environment install under share/."""
    share = Path(sys.prefix) / "share"
    return [path for kind in ("msg", "srv", "action")
            for path in sorted(share.glob(f"*/{kind}/*.{kind}"))]


def test_every_installed_interface_reads_as_its_generated_class() -> None:
    """The oracle: the table was read from the generated classes of the Jazzy wheels."""
    table = read("message_fields").values
    compared = 0
    for path in _installed_interface_files():
        package, kind = path.parts[-3], path.parts[-2]
        found = definitions(package, kind, path.stem, path.read_text(encoding="utf-8"))
        assert found, path
        for name, entry in found.items():
            if name in table:
                assert sorted(entry.split()) == sorted(table[name].split()), name
                compared += 1
    assert compared > 150


@pytest.mark.parametrize(("written", "field"), [
    ("float64 x", "x:double"), ("bool on", "on:boolean"), ("byte b", "b:octet"),
    ("char c", "c:uint8"), ("float32[] xs", "xs:sequence<float>"),
    ("int32[4] xs", "xs:int32[4]"), ("uint8[<=8] xs", "xs:sequence<uint8,8>"),
    ("string<=10 name", "name:string<10>"), ("string<=10[] names", "names:sequence<string<10>>"),
    ("Header header", "header:std_msgs/Header"), ("Point p", "p:demo_msgs/Point"),
    ("geometry_msgs/Point[] ps", "ps:sequence<geometry_msgs/Point>"),
])
def test_field_types_are_those_of_the_generated_class(written: str, field: str) -> None:
    assert definitions("demo_msgs", "msg", "M", written) == {"demo_msgs/msg/M": field}


def test_constants_defaults_comments_and_sections() -> None:
    text = "# A goal.\nint32 MAX=5  # the most\nstring NAME=\"a # b\"\nfloat64 x 1.5\n---\n" \
           "bool done\n---\n"
    assert definitions("demo_msgs", "action", "Go", text) == {
        "demo_msgs/action/Go_Goal": "MAX NAME x:double X__DEFAULT",
        "demo_msgs/action/Go_Result": "done:boolean",
        "demo_msgs/action/Go_Feedback": ""}


@pytest.mark.parametrize("text", [
    "float64\n", "float64 X\n", "int32 x\n---\nbool y\n", "long x\n[] y\n", "bool[<=] x\n",
    "float64<=3 x\n",
])
def test_a_line_not_understood_leaves_the_whole_file_unknown(text: str) -> None:
    assert definitions("demo_msgs", "msg", "M", text) == {}


def test_the_workspace_index_keeps_them_through_the_cache(tmp_path: Path) -> None:
    (tmp_path / "msg").mkdir()
    (tmp_path / "msg" / "Reading.msg").write_text("float64 value\n")
    (tmp_path / "package.xml").write_text("<package><name>demo_msgs</name></package>")
    package = read_workspace_package(tmp_path)
    assert package.messages == {"demo_msgs/msg/Reading": "value:double"}
    assert index_entry(index_record(package)) == package
