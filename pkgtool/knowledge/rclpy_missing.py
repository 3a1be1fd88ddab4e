"""Attributes people reach for on rclpy (often from rospy or a tutorial) that do not exist.

Every entry was checked against rclpy 7.1.6 (Jazzy) with every rclpy submodule imported (see
tests/lint/test_dependencies_knowledge.py): accessing it raises AttributeError.
"""

from __future__ import annotations

_CLASSES = {
    "rclpy.action.ActionClient": ("rclpy.action.client.ActionClient",),
    "rclpy.action.ActionServer": ("rclpy.action.server.ActionServer",),
    "rclpy.time.Time": (),
    "rclpy.duration.Duration": (),
}
"""Canonical class path -> other import paths of the same class."""

_MISSING: dict[str, dict[str, str]] = {
    "rclpy.action.ActionClient": {
        "GoalStatus": "`from action_msgs.msg import GoalStatus`"},
    "rclpy.action.ActionServer": {
        "GoalStatus": "`from action_msgs.msg import GoalStatus`"},
    "rclpy.time.Time": {
        "now": "`node.get_clock().now()`",
        "to_sec": "`time.nanoseconds / 1e9`",
        "from_sec": "`Time(seconds=...)`"},
    "rclpy.duration.Duration": {
        "from_sec": "`Duration(seconds=...)`",
        "to_sec": "`duration.nanoseconds / 1e9`"},
    "rclpy": {
        "Node": "`from rclpy.node import Node`",
        "Time": "`from rclpy.time import Time`",
        "Duration": "`from rclpy.duration import Duration`",
        "Rate": "`node.create_rate(hz)`",
        "Publisher": "`node.create_publisher(...)`",
        "Subscriber": "`node.create_subscription(...)`",
        "init_node": "`rclpy.init()` and `rclpy.create_node(name)`",
        "is_shutdown": "`not rclpy.ok()`",
        "signal_shutdown": "`rclpy.shutdown()`",
        "sleep": "a rate from `node.create_rate(hz)`",
        "get_time": "`node.get_clock().now()`",
        "get_rostime": "`node.get_clock().now()`",
        "get_param": "`node.get_parameter(name).value`",
        "get_logger": "`rclpy.logging.get_logger(name)` or `node.get_logger()`",
        "loginfo": "`node.get_logger().info(...)`",
        "logwarn": "`node.get_logger().warning(...)`",
        "logerr": "`node.get_logger().error(...)`",
        "logdebug": "`node.get_logger().debug(...)`",
        "logfatal": "`node.get_logger().fatal(...)`",
    },
}


def canonical(qualified: str) -> str:
    """The canonical path of an rclpy class imported under another path."""
    for name, aliases in _CLASSES.items():
        if qualified in aliases:
            return name
    return qualified


def missing_attribute(owner: str, attr: str) -> str | None:
    """What to use instead of ``owner.attr`` when rclpy has no such attribute, else None."""
    return _MISSING.get(canonical(owner), {}).get(attr)


def entries() -> list[tuple[str, str]]:
    """Every (owner, attribute) pair of the table, for tests."""
    return [(owner, attr) for owner, attrs in _MISSING.items() for attr in attrs]


def owners() -> dict[str, tuple[str, ...]]:
    """Canonical class paths and their other import paths, for tests."""
    return dict(_CLASSES)
