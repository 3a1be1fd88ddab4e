"""Node kinds of ``pkgtool create --node NAME:KIND[:TYPE]`` and the interfaces they use."""

from __future__ import annotations

import re
from dataclasses import dataclass

from pkgtool.create import CreateError

_TYPE = re.compile(r"^([a-z][a-z0-9_]*)/(msg|srv|action)/([A-Z][A-Za-z0-9]*)$")

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


_GENERATED_NAMES = frozenset({"Node", "Parameter", "ActionServer", "ActionClient", "GoalStatus",
                              "ExternalShutdownException"})
"""Names the generated modules import besides the interface type."""


@dataclass(frozen=True, slots=True)
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
         (("topic", "chatter"), ("period", 0.5))),
    Kind("subscriber", "msg", "log the messages of a topic", (("topic", "chatter"),)),
    Kind("service", "srv", "answer service requests", (("service_name", None),)),
    Kind("client", "srv", "call a service periodically",
         (("service_name", None), ("period", 1.0))),
    Kind("action-server", "action", "execute action goals", (("action_name", None),)),
    Kind("action-client", "action", "send an action goal and wait for its result",
         (("action_name", None),)),
    Kind("timer", None, "do periodic work", (("period", 1.0),)),
)}


@dataclass(frozen=True, slots=True)
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


@dataclass(frozen=True, slots=True)
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
    def parameters(self) -> tuple[tuple[str, object], ...]:
        """Declared parameters and their defaults, in declaration order."""
        found = [(key, self.interface.snake if value is None and self.interface else value)
                 for key, value in self.kind.parameters]
        if self.kind.name == "action-client" and self.example == "fibonacci":
            found.append(("order", 10))
        return tuple(found)


def parse_interface(text: str, family: str) -> Interface:
    """``pkg/family/Name`` as an :class:`Interface`, or ValueError saying what is wrong."""
    match = _TYPE.match(text)
    if not match or match.group(2) != family:
        raise ValueError(f"Invalid {family} type `{text}`: write it as "
                         f"`package/{family}/Name`, e.g. `{DEFAULT_TYPES[family]}`.")
    if match.group(3) in _GENERATED_NAMES:
        raise ValueError(f"The {family} type `{text}` has the name of a class the generated "
                         "code imports from rclpy: rename the type or write the node by hand.")
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
