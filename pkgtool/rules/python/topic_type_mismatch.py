"""PYC021: a subscription of a message type no publisher of the package sends on its topic."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.endpoints import type_mismatches
from pkgtool.rules.registry import rule


@rule("PYC021", "topic-type-mismatch", Severity.ERROR,
      fix="Use the same message type on both sides of the topic, or another topic name")
def topic_type_mismatch(package: Package) -> Iterator[Hit]:
    """A subscription takes another message type than the package's publishers send on its
    topic.

    ## What it does
    Pairs the `create_publisher` and `create_subscription` calls of the package's installed
    modules by topic name, when the name is certain: a string literal, a name bound once
    to one, or a parameter read (`self.get_parameter('topic').value`) whose declaration's
    literal default no parameter or launch file of the package may change. Reports a
    subscription whose message class (imported by name, `pkg.msg.Name`) is none of the
    classes the publishers of the same topic name use, when all of those are known.
    Private names (`~/x`) are left out, and so are packages with C or C++ sources (their
    native nodes publish too, unseen).

    ## Why is this bad?
    ROS 2 connects a publisher and a subscription only when their types match: the
    subscription never receives anything, and `ros2 topic info` shows two types for the
    topic. It typically follows a change of the message type on one side only.

    ## Example
    ```python
    self.create_publisher(String, 'chatter', 10)              # talker.py
    self.create_subscription(Int32, 'chatter', self.on_message, 10)  # listener.py
    ```

    ## Use instead
    ```python
    self.create_publisher(String, 'chatter', 10)
    self.create_subscription(String, 'chatter', self.on_message, 10)
    ```
    """
    for subscription, publishers, types in type_mismatches(package):
        yield Hit(subscription.type_span,
                  f"The subscription to `{subscription.topic}` takes `{subscription.type}`, but "
                  f"this package publishes {types} on it: the types differ, so it never "
                  "receives a message", related=tuple(p.type_span for p in publishers))
