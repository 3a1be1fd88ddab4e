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


def test_unknown_license_lists_the_valid_ones(tmp_path: Path) -> None:
    with pytest.raises(CreateError) as error:
        validate(request(tmp_path, license="GPL-3.0"))
    assert all(spdx in str(error.value) for spdx in LICENSES)


@pytest.mark.parametrize("node, message", [
    ("talker:broadcaster", "Unknown node kind `broadcaster`"),
    ("talker", "Unknown node kind ``"),
    ("Talker:publisher", "Invalid node name `Talker`"),
    ("flake8:timer", "Invalid node name `flake8`"),
    ("talker:publisher:std_msgs/String", "Invalid msg type"),
    ("talker:publisher:std_srvs/srv/Trigger", "Invalid msg type"),
    ("beat:timer:std_msgs/msg/String", "uses no interface"),
    ("talker:publisher:my_msgs/msg/Node", "has the name of a class"),
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
