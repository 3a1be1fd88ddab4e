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
    "rclpy.publisher.Publisher": (),
    "rclpy.subscription.Subscription": (),
    "rclpy.timer.Timer": (),
    "rclpy.service.Service": (),
    "rclpy.task.Future": (),
    "rclpy.parameter.Parameter": (),
}
"""Canonical class path -> other import paths of the same class."""

_PARAMETER_VALUE_FIELDS = tuple(f"{kind}_value" for kind in (
    "bool", "integer", "double", "string", "byte_array", "bool_array", "integer_array",
    "double_array", "string_array"))
"""The fields of the ``ParameterValue`` message, which a ``Parameter`` does not have."""
_MISSING: dict[str, dict[str, str]] = {
    "rclpy.action.ActionClient": {
        "GoalStatus": "`from action_msgs.msg import GoalStatus`"},
    "rclpy.action.ActionServer": {
        "GoalStatus": "`from action_msgs.msg import GoalStatus`"},
    "rclpy.time.Time": {
        "now": "`node.get_clock().now()`",
        "to_sec": "`time.nanoseconds / 1e9`",
        "from_sec": "`Time(seconds=...)`",
        "to_nsec": "`time.nanoseconds`",
        "seconds": "`time.nanoseconds / 1e9`",
        "sec": "`time.seconds_nanoseconds()[0]`, or `time.to_msg().sec` for the message field",
        "nanosec": "`time.seconds_nanoseconds()[1]`, or `time.to_msg().nanosec`",
        "secs": "`time.seconds_nanoseconds()[0]`",
        "nsecs": "`time.seconds_nanoseconds()[1]`"},
    "rclpy.duration.Duration": {
        "from_sec": "`Duration(seconds=...)`",
        "to_sec": "`duration.nanoseconds / 1e9`",
        "to_nsec": "`duration.nanoseconds`",
        "seconds": "`duration.nanoseconds / 1e9`",
        "sec": "`duration.nanoseconds // 10**9`, or `duration.to_msg().sec`",
        "secs": "`duration.nanoseconds // 10**9`"},
    "rclpy.publisher.Publisher": {
        "get_num_connections": "`publisher.get_subscription_count()`",
        "unregister": "`node.destroy_publisher(publisher)`",
        "name": "`publisher.topic_name`",
        "resolved_name": "`publisher.topic_name`"},
    "rclpy.subscription.Subscription": {
        "get_num_connections": "`subscription.get_publisher_count()`",
        "unregister": "`node.destroy_subscription(subscription)`",
        "name": "`subscription.topic_name`",
        "resolved_name": "`subscription.topic_name`"},
    "rclpy.timer.Timer": {
        "start": "`timer.reset()` (a timer runs from its creation; `reset()` restarts a "
                 "cancelled one)",
        "stop": "`timer.cancel()`",
        "shutdown": "`timer.cancel()`, or `node.destroy_timer(timer)`"},
    "rclpy.service.Service": {
        "call": "a client: `node.create_client(...)`, then `client.call_async(request)`",
        "call_async": "a client: `node.create_client(...)`, then `client.call_async(request)`",
        "wait_for_service": "a client's `wait_for_service()`: a service does not wait for "
                            "itself"},
    "rclpy.parameter.Parameter": {
        **{field: f"`parameter.value`, or `parameter.get_parameter_value().{field}`"
           for field in _PARAMETER_VALUE_FIELDS},
        "get_value": "`parameter.value`",
        "parameter_value": "`parameter.get_parameter_value()`"},
    "rclpy.task.Future": {
        "get_result": "`future.result()`",
        "get": "`future.result()`",
        "is_done": "`future.done()`"},
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
