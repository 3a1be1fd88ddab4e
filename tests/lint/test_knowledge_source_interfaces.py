"""The interface packages without wheels, read from their repositories per distribution."""

from __future__ import annotations

from pkgtool.knowledge import interfaces, message_fields
from pkgtool.knowledge.generate_source_interfaces import PACKAGES, tables
from pkgtool.knowledge.tables import DATA


def test_the_shipped_tables_know_the_packages_courses_use_per_distribution() -> None:
    for distro in ("humble", "jazzy"):
        for package in ("turtlesim", "example_interfaces", "tf2_msgs"):
            assert interfaces.is_known_package(package, distro), (package, distro)
        assert interfaces.interface_kind("turtlesim", "Spawn", distro) == "srv"
    assert interfaces.is_known_package("nav2_msgs", "jazzy")
    assert not interfaces.is_known_package("nav2_msgs", "humble")  # other names: unknown
    assert interfaces.is_known_package("irobot_create_msgs", "humble")
    assert not interfaces.is_known_package("irobot_create_msgs", "jazzy")  # no jazzy branch
    assert not interfaces.is_known_package("turtlesim", "rolling")
    assert set(PACKAGES) >= {line.split()[0] for line in
                             (DATA / "source_interfaces.txt").read_text().splitlines()
                             if line and line[0] not in "#@s"}


def test_fields_of_the_source_packages() -> None:
    pose = message_fields.message_of("turtlesim.msg.Pose")
    assert pose is not None and list(pose.fields) == [
        "x", "y", "theta", "linear_velocity", "angular_velocity"]
    added = message_fields.message_of("example_interfaces.srv.AddTwoInts.Response", "humble")
    assert added is not None and added.fields == {"sum": "int64"}
    goal = message_fields.message_of("nav2_msgs.action.NavigateToPose.Goal")
    assert goal is not None
    stamped = message_fields.nested_message(goal, "pose")
    assert stamped is not None and stamped.name == "geometry_msgs/msg/PoseStamped"
    assert message_fields.message_of("turtlesim.srv.Spawn.Event") is None  # not read
    box = message_fields.message_of("vision_msgs.msg.BoundingBox2D", "humble")
    centre = message_fields.nested_message(box, "center") if box else None
    assert centre is not None and list(centre.fields) == ["position", "theta"]  # 4.x, not x/y


def test_what_the_distributions_share_takes_both_flags_and_jazzy_wins_a_difference() -> None:
    same = {"demo_msgs/msg/A": "x:double"}
    found = {"humble": {"demo_msgs": {**same, "demo_msgs/msg/B": "y:int32"},
                        "old_msgs": {"old_msgs/msg/C": ""}},
             "jazzy": {"demo_msgs": {**same, "demo_msgs/msg/B": "y:int64"}}}
    texts = tables(found, ["humble x/y@1", "jazzy x/y@2"])
    assert texts["source_interfaces"].split("\n@", 1)[1] == (
        "h\nold_msgs msg:C\n@hj\ndemo_msgs msg:A,B\n")
    assert texts["source_message_fields"].split("\n@", 1)[1] == (
        "h\nold_msgs/msg/C\n@hj\ndemo_msgs/msg/A x:double\n@j\ndemo_msgs/msg/B y:int64\n")
