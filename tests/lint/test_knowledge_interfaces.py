"""The shipped interface table against the installed ROS 2 Jazzy wheels (real rosidl modules)."""

from __future__ import annotations

import importlib
import inspect

import pytest

from pkgtool.knowledge import interfaces
from pkgtool.knowledge.generate_interfaces import table
from pkgtool.knowledge.tables import DATA, read


def _packages() -> list[str]:
    return sorted(read("interfaces").values)


def test_shipped_table_is_what_the_generator_reads_from_the_installed_wheels() -> None:
    assert (DATA / "interfaces.txt").read_text(encoding="utf-8") == table(), (
        "interfaces.txt is stale: run python -m pkgtool.knowledge.generate_interfaces")
    assert {"std_msgs", "geometry_msgs", "std_srvs", "test_msgs", "sensor_msgs"} <= set(
        _packages())


@pytest.mark.ros
@pytest.mark.parametrize("package", _packages())
def test_every_interface_is_a_class_of_the_generated_python_module(package: str) -> None:
    """``from <package>.<kind> import <Name>`` works for exactly the names in the table."""
    known = interfaces.interfaces_of(package)
    assert known is not None
    for kind in interfaces.KINDS:
        try:
            module = importlib.import_module(f"{package}.{kind}")
        except ModuleNotFoundError:
            assert kind not in known, f"{package}.{kind} is not importable"
            continue
        # rosidl names are PascalCase; `Name_Request`, `Name_SendGoal_Event`... are parts
        classes = {name for name, value in vars(module).items()
                   if inspect.isclass(value) and "_" not in name
                   and value.__module__.startswith(f"{package}.{kind}.")}
        assert classes == known.get(kind, frozenset()), (package, kind)


def test_lookups() -> None:
    assert interfaces.interface_kind("std_msgs", "String") == "msg"
    assert interfaces.interface_kind("std_srvs", "Trigger") == "srv"
    assert interfaces.interface_kind("test_msgs", "Fibonacci") == "action"
    assert interfaces.interface_kind("std_msgs", "NoSuch") is None
    assert interfaces.is_known_package("std_msgs")
    assert not interfaces.is_known_package("px4_msgs")  # unknown: never reported


@pytest.mark.parametrize(("text", "problem"), [
    ("std_msgs/msg/String", None),
    ("geometry_msgs/Twist", None),
    ("test_msgs/srv/BasicTypes", None),  # a message and a service of the same name
    ("test_msgs/msg/BasicTypes", None),
    ("nav2_msgs/action/NavigateToPose", None),
    ("std_msgs/msg/NoSuch", "`std_msgs` has no message `NoSuch`"),
    ("geometry_msgs/msg/Twsit",
     "`geometry_msgs` has no message `Twsit` (did you mean `geometry_msgs/msg/Twist`?)"),
    ("std_srvs/msg/Trigger",
     "`std_srvs/Trigger` is a service, not a message: write `std_srvs/srv/Trigger`"),
])
def test_type_problem(text: str, problem: str | None) -> None:
    parsed = interfaces.parse_type(text)
    assert parsed is not None
    assert interfaces.type_problem(*parsed) == problem


def test_workspace_interfaces_override_the_table() -> None:
    mine = {"msg": frozenset({"Reading"})}
    assert interfaces.type_problem("my_msgs", "msg", "Reading", mine) is None
    assert interfaces.type_problem("my_msgs", "msg", "Readng", mine) == (
        "`my_msgs` has no message `Readng` (did you mean `my_msgs/msg/Reading`?)")
    assert interfaces.parse_type("not a type") is None


def test_the_table_speaks_for_jazzy_only() -> None:
    assert interfaces.interface_kind("std_msgs", "String", "jazzy") == "msg"
    assert not interfaces.is_known_package("std_msgs", "rolling")
    assert interfaces.type_problem("std_msgs", "msg", "NoSuch", distro="humble") is None


@pytest.mark.parametrize(("word", "kind"), [
    ("msgs", "msg"), ("Msg", "msg"), ("messages", "msg"), ("srvs", "srv"), ("Service", "srv"),
    ("actions", "action"), ("msg", None), ("srv", None), ("action", None), ("utils", None),
    ("ms", None), ("acton", "action"), ("mesage", "msg"), ("src", None),
])
def test_meant_kind(word: str, kind: str | None) -> None:
    assert interfaces.meant_kind(word) == kind
