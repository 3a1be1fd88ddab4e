"""The shipped message field table against the installed ROS 2 Jazzy wheels' Python classes, and
the table of messages defined alike on other distributions against the wheels' definitions."""

from __future__ import annotations

import importlib
from pathlib import Path

import pytest

from pkgtool.knowledge import message_fields
from pkgtool.knowledge.generate_message_distros import (definitions, digest,
                                                        installed_definitions, sections)
from pkgtool.knowledge.generate_message_fields import table
from pkgtool.knowledge.tables import DATA, read


def test_shipped_table_is_what_the_generator_reads_from_the_installed_wheels() -> None:
    text = (DATA / "message_fields.txt").read_text(encoding="utf-8")
    assert text == table(), (
        "message_fields.txt is stale: run python -m pkgtool.knowledge.generate_message_fields")
    assert len(text.encode()) < 100_000, "keep the table small: lint reads it on first use"


def test_every_interface_package_of_the_interface_table_has_its_messages() -> None:
    packages = {name.split("/")[0] for name in read("message_fields").flags}
    assert packages == set(read("interfaces").values)


@pytest.mark.parametrize(("dotted", "attribute"), [
    ("std_msgs.msg.String", "data"),
    ("geometry_msgs.msg.Twist", "linear"),
    ("std_srvs.srv.Trigger.Response", "success"),
    ("std_srvs.srv.SetBool_Request", "data"),
    ("test_msgs.action.Fibonacci.Goal", "order"),
    ("test_msgs.action.Fibonacci.Feedback", "sequence"),
    ("sensor_msgs.msg.NavSatStatus", "STATUS_FIX"),
    ("sensor_msgs.msg.NavSatStatus", "STATUS__DEFAULT"),
    ("action_msgs.msg.GoalStatus", "get_fields_and_field_types"),
])
def test_attributes_the_classes_have(dotted: str, attribute: str) -> None:
    message = message_fields.message_of(dotted)
    assert message is not None and message.has(attribute)


@pytest.mark.ros
@pytest.mark.parametrize("dotted", ["std_msgs.msg.String", "geometry_msgs.msg.PoseStamped",
                                    "std_srvs.srv.Trigger.Request",
                                    "test_msgs.action.Fibonacci.Result",
                                    "sensor_msgs.msg.NavSatStatus"])
def test_public_attributes_are_those_of_an_instance(dotted: str) -> None:
    """What ``has`` says matches ``dir()`` of a real instance, names starting with ``_`` aside."""
    path, _, name = dotted.rpartition(".")
    owner = importlib.import_module(path) if path.count(".") == 1 else getattr(
        importlib.import_module(path.rpartition(".")[0]), path.rpartition(".")[2])
    instance = getattr(owner, name)()
    message = message_fields.message_of(dotted)
    assert message is not None
    public = {a for a in dir(instance) if not a.startswith("_")}
    assert {a for a in public if message.has(a)} == public
    assert not message.has("no_such_field")


def test_nested_messages_and_near_misses() -> None:
    pose = message_fields.message_of("geometry_msgs.msg.PoseStamped")
    assert pose is not None
    header = message_fields.nested_message(pose, "header")
    assert header is not None and header.name == "std_msgs/msg/Header"
    stamp = message_fields.nested_message(header, "stamp")
    assert stamp is not None and stamp.name == "builtin_interfaces/msg/Time"
    assert message_fields.nested_message(header, "frame_id") is None  # a string
    path = message_fields.message_of("nav_msgs.msg.Path")
    assert path is not None and message_fields.nested_message(path, "poses") is None  # sequence
    assert message_fields.close_field(stamp, "secs") == "sec"
    assert message_fields.close_field(pose, "Header") == "header"
    assert message_fields.close_field(pose, "zzz") is None


def test_unknown_names_and_other_distributions() -> None:
    assert message_fields.message_of("px4_msgs.msg.VehicleCommand") is None
    assert message_fields.message_of("std_msgs.msg.NoSuch") is None
    assert message_fields.message_of("std_msgs.String") is None
    assert message_fields.message_of("std_msgs.msg.String", "kilted") is None
    assert message_fields.message_of("std_msgs.msg.String", "rolling") is None  # may change
    assert message_fields.message_of("sensor_msgs.msg.Range", "humble") is None  # + variance
    assert message_fields.message_of("std_srvs.srv.Trigger_Event", "humble") is None
    assert message_fields.message_of("std_srvs.srv.Trigger_Request", "humble") is None


def test_messages_defined_alike_are_known_on_their_distributions() -> None:
    string = message_fields.message_of("std_msgs.msg.String", "humble")
    assert string is not None and list(string.fields) == ["data"]
    trigger = message_fields.message_of("std_srvs.srv.Trigger.Response", "humble")
    assert trigger is not None and trigger.has("success")
    imu = message_fields.message_of("sensor_msgs.msg.Imu", "humble")
    assert imu is not None
    header = message_fields.nested_message(imu, "header")
    assert header is not None and header.distro == "humble"
    assert message_fields.constructor_options("humble") == frozenset()
    assert "check_fields" in message_fields.constructor_options("jazzy")


def test_alike_table_matches_the_installed_definitions() -> None:
    """Each listed message is in the field table and its Jazzy definition is still the one it
    was compared with (else: regenerate with the sources the table's ``source`` lines name)."""
    alike = read("message_distros")
    installed = installed_definitions()
    assert alike.flags and set(alike.flags) <= set(read("message_fields").flags)
    stale = [name for name, value in alike.values.items()
             if name not in installed or digest(installed[name]) != value]
    assert not stale, f"message_distros.txt is stale for {stale[:5]}"
    assert all("j" not in flags for flags in alike.flags.values())


def test_definitions_of_interface_files(tmp_path: Path) -> None:
    assert sections("# doc\nint32 a  # the a\n\n---\nbool ok\nstring  NAME=\"x\"\n") == [
        ("int32 a",), ("bool ok", 'string NAME="x"')]
    files = {"pkg/msg/A.msg": "int32 a\n", "pkg/srv/S.srv": "int32 a\n---\n",
             "pkg/action/F.action": "int32 g\n---\n---\nint32 f\n",
             "pkg/srv/Bad.srv": "int32 a\n", "pkg/msg/A.idl": "module pkg {};\n"}
    for name, text in files.items():
        (tmp_path / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / name).write_text(text)
    assert definitions(tmp_path.glob("*/*/*.*")) == {
        "pkg/msg/A": ("int32 a",), "pkg/srv/S_Request": ("int32 a",), "pkg/srv/S_Response": (),
        "pkg/action/F_Goal": ("int32 g",), "pkg/action/F_Result": (),
        "pkg/action/F_Feedback": ("int32 f",)}
