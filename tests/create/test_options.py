"""Guards of ``pkgtool create``: bad names, licenses, kinds, types and dependencies are refused."""

from __future__ import annotations

from pathlib import Path

import pytest

from pkgtool.create import CreateError
from pkgtool.create.licenses import LICENSES
from pkgtool.create.options import validate
from tests.create.conftest import request


@pytest.mark.parametrize("name", ["my-pkg", "MyPkg", "my_Pkg", "1pkg", "_pkg", "my__pkg",
                                  "pkg_", "test", "x", "class", "json", "a" * 41, "my pkg", ""])
def test_invalid_package_names_are_refused(tmp_path: Path, name: str) -> None:
    with pytest.raises(CreateError, match="Invalid package name"):
        validate(request(tmp_path, name))


@pytest.mark.parametrize("name", ["my_pkg", "pkg2", "a1_b2_c3", "ab"])
def test_rep_144_names_are_accepted(tmp_path: Path, name: str) -> None:
    assert validate(request(tmp_path, name)).name == name


@pytest.mark.parametrize("name", ["rclpy", "std_msgs", "launch", "turtlesim", "nav2_msgs"])
def test_names_of_released_ros_packages_are_refused(tmp_path: Path, name: str) -> None:
    with pytest.raises(CreateError, match=f"Invalid package name `{name}`: a ROS package of "
                       "that name is released for jazzy"):
        validate(request(tmp_path, name))


def test_types_of_packages_the_table_does_not_know_are_trusted(tmp_path: Path) -> None:
    plan = validate(request(tmp_path, nodes=("talker:publisher:my_msgs/msg/Anything",)))
    assert plan.nodes[0].interface.full == "my_msgs/msg/Anything"


@pytest.mark.parametrize("name, reason", [
    ("pytest", "`colcon test` runs every package's tests with pytest"),
    ("setuptools", "colcon builds every ament_python package with setuptools"),
    ("numpy", "rosdep key `python3-numpy`"),
    ("yaml", "rosdep key `python3-yaml`"),
])
def test_names_of_python_modules_are_refused_with_the_reason(tmp_path: Path, name: str,
                                                             reason: str) -> None:
    with pytest.raises(CreateError, match=f"Invalid package name `{name}`.*{reason}"):
        validate(request(tmp_path, name))
    assert validate(request(tmp_path, nodes=(f"{name}_node:timer",), library_name=name))


@pytest.mark.parametrize("given, value, expression, warned", [
    ("MIT", "MIT", "MIT", False),
    ("apache-2.0", "Apache-2.0", "Apache-2.0", False),
    ("BSD-2.0", "BSD-3-Clause", "BSD-3-Clause", True),  # ament_copyright's name, renamed
    ("gpl-2.0-or-later with classpath-exception-2.0",
     "GPL-2.0-or-later WITH Classpath-exception-2.0",
     "GPL-2.0-or-later WITH Classpath-exception-2.0", True),
    ("(MIT OR Apache-2.0) AND BSL-1.0", "(MIT OR Apache-2.0) AND BSL-1.0",
     "(MIT OR Apache-2.0) AND BSL-1.0", True),
    ("Proprietary", "Proprietary", "LicenseRef-Proprietary", True),
    ("All rights reserved", "All rights reserved", "LicenseRef-All-rights-reserved", True),
])
def test_any_license_is_taken_with_a_warning_when_no_text_ships(
        tmp_path: Path, given: str, value: str, expression: str, warned: bool) -> None:
    plan = validate(request(tmp_path, license=given))
    assert (plan.license, plan.license_expression) == (value, expression)
    assert bool(plan.warnings) == warned
    assert plan.license_shipped == (value in LICENSES)
    assert ("ament_copyright" in plan.test_depends) == plan.license_shipped


def test_a_misspelt_license_gets_a_suggestion(tmp_path: Path) -> None:
    (warning,) = validate(request(tmp_path, license="Apache 2.0")).warnings
    assert "did you mean `Apache-2.0`?" in warning and "No LICENSE text ships" in warning


@pytest.mark.parametrize("license_", ["", "  ", "a\nb", "x" * 101])
def test_empty_or_multiline_licenses_are_refused(tmp_path: Path, license_: str) -> None:
    with pytest.raises(CreateError, match="Invalid license"):
        validate(request(tmp_path, license=license_))


@pytest.mark.parametrize("values, message", [
    ({"msg": "std_msgs/msg/Int32", "nodes": ("beat:timer",)},
     "--msg `std_msgs/msg/Int32` is for publisher or subscriber nodes"),
    ({"srv": "std_srvs/srv/Empty"}, "add `--node NAME:service`"),
    ({"action": "test_msgs/action/Fibonacci", "nodes": ("a1:action-server:test_msgs/action/"
                                                        "NestedMessage",)},
     "is for action-server or action-client nodes"),
])
def test_type_options_that_reach_no_node_are_refused(tmp_path: Path, values: dict,
                                                     message: str) -> None:
    with pytest.raises(CreateError, match=message.replace("(", r"\(")):
        validate(request(tmp_path, **values))


@pytest.mark.parametrize("node, topic", [
    ("talker:publisher", "chatter"),
    ("drive:publisher:geometry_msgs/msg/Twist", "cmd_vel"),
    ("lidar:subscriber:sensor_msgs/msg/LaserScan", "scan"),
    ("odometry:subscriber:nav_msgs/msg/Odometry", "odom"),
    ("level:publisher:std_msgs/msg/Float64", "float64"),
])
def test_the_default_topic_comes_from_the_type(tmp_path: Path, node: str, topic: str) -> None:
    (spec,) = validate(request(tmp_path, nodes=(node,))).nodes
    assert spec.topic == topic and dict(spec.parameters)["topic"] == topic


@pytest.mark.parametrize("node, message", [
    ("talker:broadcaster", "Unknown node kind `broadcaster`"),
    ("talker", "Unknown node kind ``"),
    ("Talker:publisher", "Invalid node name `Talker`"),
    ("flake8:timer", "Invalid node name `flake8`"),
    ("talker:publisher:std_msgs/String", "Invalid msg type"),
    ("talker:publisher:std_srvs/srv/Trigger", "Invalid msg type"),
    ("beat:timer:std_msgs/msg/String", "uses no interface"),
    ("talker:publisher:my_msgs/msg/Node", "has the name of a class"),
    ("talker:publisher:std_msgs/msg/NoSuch", "`std_msgs` has no message `NoSuch`"),
    ("talker:publisher:std_msgs/msg/Strng", "did you mean `std_msgs/msg/String`?"),
    ("talker:publisher:std_srvs/msg/Trigger", "is a service, not a message"),
    ("ask:client:std_srvs/srv/Trigr", "did you mean `std_srvs/srv/Trigger`?"),
])
def test_bad_nodes_are_refused(tmp_path: Path, node: str, message: str) -> None:
    with pytest.raises(CreateError, match=message.replace("(", r"\(")):
        validate(request(tmp_path, nodes=(node,)))


def test_duplicate_node_names_are_refused(tmp_path: Path) -> None:
    with pytest.raises(CreateError, match="used twice"):
        validate(request(tmp_path, nodes=("talker:publisher", "talker:subscriber")))
    with pytest.raises(CreateError, match="used twice"):
        validate(request(tmp_path, nodes=("util:timer",), library_name="util"))


def test_type_options_apply_to_their_kinds(tmp_path: Path) -> None:
    nodes = ("talker:publisher", "server:service", "twist:subscriber:geometry_msgs/msg/Twist")
    plan = validate(request(tmp_path, nodes=nodes, msg="sensor_msgs/msg/Image",
                            srv="std_srvs/srv/SetBool"))
    types = {node.name: node.interface.full for node in plan.nodes if node.interface}
    assert types == {"talker": "sensor_msgs/msg/Image", "server": "std_srvs/srv/SetBool",
                     "twist": "geometry_msgs/msg/Twist"}
    assert plan.depends == ("geometry_msgs", "rclpy", "sensor_msgs", "std_srvs")


def test_dependencies_land_where_they_belong(tmp_path: Path) -> None:
    plan = validate(request(tmp_path, dependencies=("numpy", "cv2", "sensor_msgs", "rclpy",
                                                    "python3-yaml"), nodes=("act:action-client",),
                            launch=True))
    assert plan.depends == ("rclpy", "sensor_msgs", "test_msgs")
    assert plan.exec_depends == ("launch", "launch_ros", "python3-numpy", "python3-opencv",
                                 "python3-yaml")
    assert plan.test_depends == ("action_msgs", "ament_copyright", "ament_flake8",
                                 "ament_pep257", "python3-pytest")


@pytest.mark.parametrize("dependency, message", [
    ("os", "standard library"),
    ("opencv-python", "use the rosdep key `python3-opencv`"),
    ("Not-A-Package!", "neither a ROS package name nor a known Python module"),
])
def test_bad_dependencies_are_refused(tmp_path: Path, dependency: str, message: str) -> None:
    with pytest.raises(CreateError, match=message):
        validate(request(tmp_path, dependencies=(dependency,)))


@pytest.mark.parametrize("values, message", [
    ({"launch": True}, "need at least one node"),
    ({"config": True}, "need at least one node"),
    ({"package_format": 1}, "Unsupported package format 1"),
    ({"maintainer_email": "nobody"}, "Invalid maintainer email"),
    ({"maintainer_name": "Jane\nDoe"}, "Invalid maintainer name"),
    ({"description": ""}, None),
    ({"library_name": "Lib"}, "Invalid library name"),
])
def test_other_values_are_checked(tmp_path: Path, values: dict, message: str | None) -> None:
    if message is None:
        assert validate(request(tmp_path, **values)).description  # empty means the default
        return
    with pytest.raises(CreateError, match=message):
        validate(request(tmp_path, **values))
