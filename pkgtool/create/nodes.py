"""Node kinds of ``pkgtool create --node NAME:KIND[:TYPE]`` and the interfaces they use."""

from __future__ import annotations

import re

from pkgtool.create import CreateError
from pkgtool.records import record
from pkgtool.lazy_regex import lazy_pattern

_TYPE = lazy_pattern(r"^([a-z][a-z0-9_]*)/(msg|srv|action)/([A-Z][A-Za-z0-9]*)$")

DEFAULT_TYPES = {
    "msg": "std_msgs/msg/String",
    "srv": "std_srvs/srv/Trigger",
    "action": "test_msgs/action/Fibonacci",
}
"""Interface per kind when none is given: all ship with ROS 2 Jazzy (and as PyPI wheels)."""

EXAMPLES = {
    "std_msgs/msg/String": "string",
    "std_srvs/srv/Trigger": "trigger",
    "std_srvs/srv/SetBool": "set_bool",
    "test_msgs/action/Fibonacci": "fibonacci",
    "example_interfaces/action/Fibonacci": "fibonacci",
    "action_tutorials_interfaces/action/Fibonacci": "fibonacci",
}
"""Interfaces whose fields the templates fill in; any other type is sent default-constructed."""


TOPICS = {
    "std_msgs/msg/String": "chatter",
    "geometry_msgs/msg/Twist": "cmd_vel", "geometry_msgs/msg/TwistStamped": "cmd_vel",
    "geometry_msgs/msg/PoseStamped": "goal_pose",
    "geometry_msgs/msg/PoseWithCovarianceStamped": "initialpose",
    "sensor_msgs/msg/LaserScan": "scan", "sensor_msgs/msg/Image": "image_raw",
    "sensor_msgs/msg/CompressedImage": "image_raw/compressed",
    "sensor_msgs/msg/CameraInfo": "camera_info", "sensor_msgs/msg/Imu": "imu",
    "sensor_msgs/msg/NavSatFix": "fix", "sensor_msgs/msg/JointState": "joint_states",
    "sensor_msgs/msg/PointCloud2": "points", "sensor_msgs/msg/BatteryState": "battery_state",
    "sensor_msgs/msg/Range": "range", "sensor_msgs/msg/Joy": "joy",
    "sensor_msgs/msg/Temperature": "temperature",
    "nav_msgs/msg/Odometry": "odom", "nav_msgs/msg/OccupancyGrid": "map",
    "nav_msgs/msg/Path": "plan",
    "diagnostic_msgs/msg/DiagnosticArray": "diagnostics",
    "visualization_msgs/msg/Marker": "visualization_marker",
    "visualization_msgs/msg/MarkerArray": "visualization_marker_array",
}
"""The topic a message type is conventionally on (as ROS drivers, Nav2 and rviz name them).

Any other type's default topic is its name in snake case (``Float64`` -> ``float64``), so a
publisher and a subscriber of one type find each other without configuration."""

_GENERATED_NAMES = frozenset({"Node", "Parameter", "ActionServer", "ActionClient", "GoalStatus",
                              "ExternalShutdownException", "CancelResponse",
                              "ReentrantCallbackGroup", "SingleThreadedExecutor",
                              "MultiThreadedExecutor"})
"""Names the generated modules import besides the interface type."""


@record
class Kind:
    """One node kind: its template, the interface family it uses and its parameters."""

    name: str
    interface: str | None
    summary: str
    parameters: tuple[tuple[str, object], ...]

    @property
    def template(self) -> str:
        """The node template under ``templates/nodes/``."""
        return f"nodes/{self.name.replace('-', '_')}.py.jinja"


KINDS = {kind.name: kind for kind in (
    Kind("publisher", "msg", "publish a message at a fixed rate",
         (("topic", None), ("period", 0.5))),
    Kind("subscriber", "msg", "log the messages of a topic", (("topic", None),)),
    Kind("service", "srv", "answer service requests", (("service_name", None),)),
    Kind("client", "srv", "call a service periodically",
         (("service_name", None), ("period", 1.0))),
    Kind("action-server", "action", "execute action goals, one step per period",
         (("action_name", None), ("period", 0.5))),
    Kind("action-client", "action", "send an action goal and wait for its result",
         (("action_name", None),)),
    Kind("timer", None, "do periodic work", (("period", 1.0),)),
)}


@record
class Interface:
    """A ROS interface type such as ``std_msgs/msg/String``."""

    package: str
    family: str
    name: str

    @property
    def full(self) -> str:
        """``package/family/Name``."""
        return f"{self.package}/{self.family}/{self.name}"

    @property
    def module(self) -> str:
        """The Python module the type is imported from."""
        return f"{self.package}.{self.family}"

    @property
    def snake(self) -> str:
        """``SetBool`` -> ``set_bool``: the default service or action name."""
        return re.sub(r"(?<=[a-z0-9])([A-Z])", r"_\1", self.name).lower()

    @property
    def topic(self) -> str:
        """The default topic of a message type: :data:`TOPICS`, else its snake-case name."""
        return TOPICS.get(self.full, self.snake)


@record
class NodeSpec:
    """One node to generate: module/executable/ROS name, kind, interface and parameters."""

    name: str
    kind: Kind
    interface: Interface | None

    @property
    def class_name(self) -> str:
        """The node class: ``my_talker`` -> ``MyTalker`` (``Node`` appended on a clash)."""
        base = "".join(part.capitalize() for part in self.name.split("_"))
        taken = _GENERATED_NAMES | {self.interface.name if self.interface else ""}
        return base + "Node" if base in taken else base

    @property
    def example(self) -> str | None:
        """Which known interface the templates fill in (``string``, ``trigger``, ...), if any."""
        return EXAMPLES.get(self.interface.full) if self.interface else None

    @property
    def executor(self) -> str:
        """The executor ``main()`` spins the node with: several threads for an action server,
        so cancel requests are served while a goal runs."""
        multi = self.kind.name == "action-server"
        return "MultiThreadedExecutor" if multi else "SingleThreadedExecutor"

    @property
    def topic(self) -> str | None:
        """The default of the ``topic`` parameter (None: the node has none)."""
        return dict(self.parameters).get("topic")  # type: ignore[return-value]

    @property
    def parameters(self) -> tuple[tuple[str, object], ...]:
        """Declared parameters and their defaults, in declaration order."""
        found = [(key, self._derived(key) if value is None else value)
                 for key, value in self.kind.parameters]
        if self.kind.name == "action-client" and self.example == "fibonacci":
            found.append(("order", 10))
        return tuple(found)

    def _derived(self, key: str) -> str:
        assert self.interface is not None, "only interface parameters default to None"
        return self.interface.topic if key == "topic" else self.interface.snake


def parse_interface(text: str, family: str) -> Interface:
    """``pkg/family/Name`` as an :class:`Interface`, or ValueError saying what is wrong."""
    match = _TYPE.match(text)
    if not match or match.group(2) != family:
        raise ValueError(f"Invalid {family} type `{text}`: write it as "
                         f"`package/{family}/Name`, e.g. `{DEFAULT_TYPES[family]}`.")
    if match.group(3) in _GENERATED_NAMES:
        raise ValueError(f"The {family} type `{text}` has the name of a class the generated "
                         "code imports from rclpy: rename the type or write the node by hand.")
    from pkgtool.knowledge.interfaces import type_problem

    problem = type_problem(match.group(1), family, match.group(3))
    if problem:  # only for packages the Jazzy interface table knows; others are trusted
        raise ValueError(f"Unknown {family} type `{text}`: {problem}.")
    return Interface(match.group(1), family, match.group(3))


def parse_node(text: str, *, msg: str | None = None, srv: str | None = None,
               action: str | None = None) -> NodeSpec:
    """``NAME:KIND[:TYPE]`` as a :class:`NodeSpec`; TYPE defaults to ``--msg/--srv/--action``.

    Raises :class:`CreateError` for an unknown kind or a malformed type.
    """
    name, _, rest = text.partition(":")
    kind_name, _, type_text = rest.partition(":")
    kind = KINDS.get(kind_name)
    if kind is None:
        raise CreateError(f"Unknown node kind `{kind_name}` in `--node {text}`: write "
                          f"NAME:KIND with KIND one of {', '.join(KINDS)}.")
    if kind.interface is None:
        if type_text:
            raise CreateError(f"A {kind.name} node uses no interface: drop `:{type_text}`.")
        return NodeSpec(name, kind, None)
    chosen = {"msg": msg, "srv": srv, "action": action}[kind.interface]
    try:
        interface = parse_interface(type_text or chosen or DEFAULT_TYPES[kind.interface],
                                    kind.interface)
    except ValueError as error:
        raise CreateError(str(error)) from None
    return NodeSpec(name, kind, interface)
