"""PYC022: a subscription whose QoS asks more than every publisher of its topic offers."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.endpoints import Endpoint, by_topic
from pkgtool.rules.registry import rule

_ASKS_MORE = {("BEST_EFFORT", "RELIABLE"): "reliability",
              ("VOLATILE", "TRANSIENT_LOCAL"): "durability"}
"""(offered, requested) policies that cannot match, and the policy they are of."""


def _conflicts(publisher: Endpoint, subscription: Endpoint) -> list[str]:
    """The policies the subscription requests above what the publisher offers."""
    if publisher.qos is None or subscription.qos is None:
        return []
    return [f"{_ASKS_MORE[pair]} {pair[1]} (the publisher offers {pair[0]})"
            for pair in zip(publisher.qos, subscription.qos) if pair in _ASKS_MORE]


@rule("PYC022", "incompatible-qos", Severity.ERROR,
      fix="Make the subscription's policy no stricter than the publisher's (e.g. both "
          "`qos_profile_sensor_data`, or a reliable publisher)")
def incompatible_qos(package: Package) -> Iterator[Hit]:
    """A subscription's QoS requests a policy that no publisher of its topic offers.

    ## What it does
    Pairs publishers and subscriptions of the package by topic name as PYC021 does, and
    compares their reliability and durability when both QoS profiles are known: a history
    depth (`10`, rclpy's default profile: reliable, volatile), rclpy's
    `qos_profile_sensor_data` (best effort) or `qos_profile_default`, or
    `QoSProfile(...)` with its policies given as `ReliabilityPolicy.X` /
    `DurabilityPolicy.X` (directly or through a name bound once and never changed).
    Reports a subscription that requests `RELIABLE` from a `BEST_EFFORT` publisher, or
    `TRANSIENT_LOCAL` from a `VOLATILE` one, when every publisher of the topic in the
    package is such (one it matches is enough: DDS connects pairs, and separate demos of
    one topic each have their own).

    ## Why is this bad?
    DDS connects a publisher and a subscription only when the offered QoS satisfies the
    requested one: here they never connect and the subscription receives nothing (rclpy
    logs at most a warning about an incompatible QoS).

    ## Example
    ```python
    self.create_publisher(LaserScan, 'scan', qos_profile_sensor_data)
    self.create_subscription(LaserScan, 'scan', self.on_scan, 10)
    ```

    ## Use instead
    ```python
    self.create_publisher(LaserScan, 'scan', qos_profile_sensor_data)
    self.create_subscription(LaserScan, 'scan', self.on_scan, qos_profile_sensor_data)
    ```
    """
    for publishers, subscriptions in by_topic(package):
        for subscription in subscriptions:
            conflicts = [_conflicts(publisher, subscription) for publisher in publishers]
            if conflicts and all(conflicts):  # one publisher it matches is enough
                others = " (and no other publisher of the package offers what it asks)" \
                    if len(publishers) > 1 else ""
                yield Hit(subscription.qos_span,
                          f"The subscription to `{subscription.topic}` requests "
                          f"{' and '.join(conflicts[0])}{others}: they never connect",
                          related=tuple(p.qos_span for p in publishers))
