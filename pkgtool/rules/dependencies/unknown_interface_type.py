"""DEP009: a `pkg/msg/Type` in a launch or parameter file that `pkg` does not define."""

from __future__ import annotations

import re
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.interfaces import type_problem
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.interface_types import interfaces_for
from pkgtool.rules.registry import rule
from pkgtool.lazy_regex import lazy_pattern

_TYPE = lazy_pattern(r"(?<![\w/.-])([a-z][a-z0-9_]*)/(msg|srv|action)/([A-Za-z]\w*)(?![\w/]|\.\w)")


def _files(package: Package) -> Iterator[str]:
    launch = {f.path for f in package.launch_files}
    for path in package.texts:
        if path in launch or (path.endswith((".yaml", ".yml"))
                              and path.split("/", 1)[0] not in ("test", "tests")):
            yield path


@rule("DEP009", "unknown-interface-type", Severity.ERROR,
      fix="Write a type the package defines, as `pkg/msg/Name`, `pkg/srv/Name` or "
          "`pkg/action/Name`")
def unknown_interface_type(package: Package) -> Iterator[Hit]:
    """A launch or YAML file names an interface type (`pkg/msg/Name`) that does not exist.

    ## What it does
    Finds interface types written as `<pkg>/msg|srv|action/<Name>` in launch files (Python,
    XML, YAML) and YAML files outside `test/` (parameters, bridge configurations) and checks
    them like DEP008: against the package's own interface folders, the workspace's interface
    packages and (for a jazzy target) pkgtool's table of the ROS 2 Jazzy interface packages.
    Unknown packages are not reported, nor types in comments, nor the values of keys naming
    a topic (`ros_topic_name: sensor_msgs/msg/navsat`); the companion types of
    services and actions (`std_srvs/srv/Trigger_Event`) count as DEP008 counts them.

    ## Why is this bad?
    Types in strings are only resolved when the launch runs: `ros2 topic pub`, a bridge or a
    recorder started with a misspelled type fails on the robot ("The passed message type is
    invalid"), not when the package is built.

    ## Example
    ```yaml
    - topic_name: /cmd_vel
      ros_type_name: geometry_msgs/msg/Twsit
    ```

    ## Use instead
    ```yaml
    - topic_name: /cmd_vel
      ros_type_name: geometry_msgs/msg/Twist
    ```
    """
    for path in _files(package):
        text = package.texts[path]
        for match in _TYPE.finditer(text):
            if _in_comment(path, text, match.start()) or _topic_value(text, match.start()):
                continue  # documentation, a line left out, a topic's name: no type
            name, kind, leaf = match.groups()
            known = interfaces_for(package, name)
            problem = None if known is None else type_problem(
                name, kind, leaf, known, package.context.distro)
            if problem:
                yield Hit(Span.of_offset(path, text, match.start()), problem)


_TOPIC_KEY = lazy_pattern(r"[\w-]*topic[\w-]*[\"']?\s*[:=]\s*[\"']?$", re.I)
"""The key of a topic's name (``ros_topic_name: ``, ``topic=\"``) just before a value."""


def _topic_value(text: str, offset: int) -> bool:
    """True when ``offset`` of ``text`` starts the value of a key naming a topic: a bridge's
    ``ros_topic_name: sensor_msgs/msg/navsat`` names a topic so spelt, not a type."""
    return _TOPIC_KEY.search(text[text.rfind("\n", 0, offset) + 1:offset]) is not None


_HASH_COMMENT = lazy_pattern(r"(?:^|\s)#")
"""Where a comment starts in a YAML or Python line (a ``#`` at the start or after a space)."""


def _in_comment(path: str, text: str, offset: int) -> bool:
    """True when ``offset`` of ``text`` (the file ``path``) is inside a comment: after a
    ``#`` of its line outside quotes (YAML, Python), or inside ``<!-- -->`` (XML)."""
    if path.endswith((".xml", ".launch")):
        return text.rfind("<!--", 0, offset) > text.rfind("-->", 0, offset)
    before = text[text.rfind("\n", 0, offset) + 1:offset]
    found = _HASH_COMMENT.search(before)
    return found is not None and before[:found.start()].count("'") % 2 == 0 and \
        before[:found.start()].count('"') % 2 == 0
