"""PYC044: a subscription to a topic nothing publishes (a client of a service nothing serves),
a typo away from one the package publishes (serves)."""

from __future__ import annotations

import re
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rosdistro import digits_differ, typo_distance, typo_of
from pkgtool.model.package import Package
from pkgtool.rules.endpoints import Endpoint, endpoints, service_endpoints
from pkgtool.rules.registry import rule


@rule("PYC044", "misspelled-topic", Severity.WARNING,
      fix="Use one topic name on both sides")
def misspelled_topic(package: Package) -> Iterator[Hit]:
    """A subscription's topic is published by nothing in the package, and is a typo away from
    a topic the package publishes with the same message type (the same for a client's
    service name and the package's services).

    ## What it does
    Takes the publishers and subscriptions of the package's installed modules whose topic
    name is certain (as PYC021 does: literals, names bound to one, parameter defaults no
    parameter or launch file changes; topics a launch file quotes, which it may remap, are
    left out). Reports a subscription whose topic no publisher of the package uses when
    exactly one published topic of the same message type is a typo away from it (one edit,
    or a swap of neighbours), unless the two differ in a digit (`robot1`, `robot2`), in
    one word of a pair names of paired topics use (`can_tx` and `can_rx`, `left`/`right`,
    `global`/`local`, `in`/`out`, `ping`/`pong`...) or in one short word wholly replaced
    (`dt/status`, `ui/status`: two namespaces): another package may publish it; or, when no
    name is a typo away, exactly one is made of the same words in another order
    (`battery_low` for `low_battery`). The
    same for a client whose service name no service of the package has, a typo away from the
    one name served with the same service type, and for rclpy's action clients and servers.

    ## Why is this bad?
    ROS 2 matches topics by exact name: `chater` never receives what is published on
    `chatter`, and nothing says so; the subscriber just waits, and a client's
    `wait_for_service()` never sees `add_two_int` served. A topic another package publishes
    (a service another package serves) under that near-miss name is possible, which is why
    this is a warning.

    ## Example
    ```python
    self.create_publisher(String, 'chatter', 10)                     # talker.py
    self.create_subscription(String, 'chater', self.on_message, 10)  # listener.py
    ```

    ## Use instead
    ```python
    self.create_subscription(String, 'chatter', self.on_message, 10)
    ```
    """
    for endpoint, meant, how in _near_misses(endpoints(package), "publisher", "subscription"):
        yield Hit(endpoint.type_span,
                  f"The subscription to `{endpoint.topic}` gets nothing this package "
                  f"publishes: it publishes `{endpoint.type}` on `{meant}`, {how} "
                  f"(did you mean `{meant}`?)")
    for action in ("", "action "):
        for endpoint, meant, how in _near_misses(service_endpoints(package),
                                                 f"{action}server", f"{action}client"):
            yield Hit(endpoint.type_span,
                      f"The {action}client of `{endpoint.topic}` calls a name nothing in this "
                      f"package serves: it serves `{endpoint.type}` as `{meant}`, {how} "
                      f"(did you mean `{meant}`?)")


def _near_misses(found: tuple[Endpoint, ...], offering: str, using: str
                 ) -> Iterator[tuple[Endpoint, str, str]]:
    """Each endpoint of kind ``using`` whose name no endpoint of kind ``offering`` has, with
    the one offered name of the same type a typo away from it, or else made of the same
    words in another order, and which of the two it is."""
    offered: dict[str, set[str | None]] = {}
    for endpoint in found:
        if endpoint.kind == offering:
            offered.setdefault(endpoint.topic.lstrip("/"), set()).add(endpoint.type)
    for endpoint in found:
        name = endpoint.topic.lstrip("/")
        if endpoint.kind != using or endpoint.type is None or name in offered:
            continue
        same_type = [t for t, types in offered.items() if types == {endpoint.type}]
        meant = typo_of(name, same_type)
        if meant is not None and not digits_differ(name, meant) and \
                not _not_a_typo(name, meant):
            yield endpoint, meant, "a typo away"
            continue
        reordered = [t for t in same_type if _words(t) == _words(name)
                     and not _DIRECTIONS & set(_words(name))]
        if len(reordered) == 1:
            yield endpoint, reordered[0], "its words in another order"


_DIRECTIONS = frozenset({"to", "from", "2", "in", "out", "vs"})
"""Words of names whose order is their meaning (``ros_to_serial``, ``serial_to_ros``)."""


def _words(name: str) -> list[str]:
    """The words of a topic or service name (parts between ``/`` and ``_``), sorted: names
    made of the same words in another order (``battery_low``, ``low_battery``) are equal."""
    return sorted(re.split(r"[/_]", name))


_OPPOSITES = frozenset(frozenset(pair.split("/")) for pair in """tx/rx in/out input/output
    left/right l/r front/back front/rear upper/lower up/down min/max start/stop on/off
    global/local request/response req/res req/resp src/dst source/target send/recv
    read/write get/set pub/sub open/close enable/disable x/y ping/pong""".split())
"""Words names of paired topics differ by (a node subscribing ``can_tx`` and publishing
``can_rx``): never a typo of each other."""


def _changed_word(name: str, other: str) -> tuple[str, str] | None:
    """The one word (parts between ``/`` and ``_``) the two names differ in, as written in
    each, or None when they differ in another number of words."""
    words, others = re.split(r"[/_]", name), re.split(r"[/_]", other)
    changed = [(a, b) for a, b in zip(words, others) if a != b]
    return changed[0] if len(words) == len(others) and len(changed) == 1 else None


def _not_a_typo(name: str, other: str) -> bool:
    """True when the two names differ in one word that is either wholly another word
    (``dt/recording_status`` and ``ui/recording_status``: two namespaces) or its partner in
    :data:`_OPPOSITES` (``can_tx``, ``can_rx``)."""
    changed = _changed_word(name, other)
    return changed is not None and (frozenset(changed) in _OPPOSITES or
                                    typo_distance(*changed, budget=9) >= min(map(len, changed)))
