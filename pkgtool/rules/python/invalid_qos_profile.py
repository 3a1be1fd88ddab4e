"""PYC018: a publisher, subscription, service or client given a literal that is no QoS profile
(``'10'``)."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import (PARAMETERS, argument, literal_type, node_api_calls,
                                    qos_calls, unpacks)
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import installed_trees

_SERVICES = ("create_service", "create_client")
_VALUES = frozenset({"NoneType", "ellipsis"})
"""Literals never reported: ``None`` (the default of some wrappers) and ``...``."""
_DEPTHS = frozenset({"int", "bool"})
PROFILES = frozenset({"rclpy.qos.QoSProfile"})
"""What ``QoSProfile`` is imported as."""
"""Literal types that are a history depth for publishers and subscriptions."""


def _wrong_type(value: ast.expr, allowed: frozenset[str]) -> str | None:
    """The type of the literal ``value`` when it is not one of ``allowed`` (nor ``None``);
    None for anything else."""
    wrong = literal_type(value)
    return None if wrong in allowed or wrong in _VALUES else wrong


def _service_literals(package: Package) -> Iterator[Hit]:
    """Literals given as ``qos_profile`` to ``create_service`` or ``create_client``, which take
    only a ``QoSProfile`` (no depth): rclpy calls ``qos_profile.get_c_qos_profile()``."""
    for module, call, method, _ in node_api_calls(package, _SERVICES):
        value = None if unpacks(call) else argument(call, PARAMETERS[method], "qos_profile")
        if value is None or (wrong := _wrong_type(value, frozenset())) is None:
            continue
        yield Hit(Span(module.path, value.lineno, value.col_offset + 1),
                  f"The QoS profile `{ast.unparse(value)}` of `{method}()` is of type `{wrong}`:"
                  " services and clients take only a `QoSProfile` (no history depth), rclpy "
                  f"raises `AttributeError: '{wrong}' object has no attribute "
                  "'get_c_qos_profile'`", "Pass a `QoSProfile` (`QoSProfile(depth=10)`)")


PRESETS = frozenset(f"rclpy.qos.qos_profile_{name}" for name in (
    "action_status_default", "best_available", "default", "parameter_events", "parameters",
    "sensor_data", "services_default", "system_default", "unknown"))
"""rclpy's predefined profiles: ``QoSProfile`` objects (Humble to Rolling), not functions."""


def _called_presets(package: Package) -> Iterator[Hit]:
    """Calls of a predefined profile (``qos_profile_sensor_data()``): a ``QoSProfile`` object
    is not callable."""
    for module, _, index in installed_trees(package):
        for call in index.calls:
            name = index.qualified(call.func) if isinstance(
                call.func, (ast.Name, ast.Attribute)) else None
            if name in PRESETS:
                text = ast.unparse(call.func)
                yield Hit(Span(module.path, call.lineno, call.col_offset + 1),
                          f"`{text}` is a `QoSProfile` object, not a function: calling it "
                          f"raises `TypeError: 'QoSProfile' object is not callable`",
                          f"Pass it without parentheses: `{text}`")


def _without_depth(package: Package) -> Iterator[Hit]:
    """``QoSProfile(...)`` calls with no ``depth`` and a history that is not given or is
    ``KEEP_LAST``: rclpy raises InvalidQoSProfileException (Foxy to Rolling)."""
    for module, _, index in installed_trees(package):
        for call in index.calls:
            if index.qualified(call.func) not in PROFILES or call.args or \
                    unpacks(call) or any(k.arg == "depth" for k in call.keywords):
                continue
            history = next((k.value for k in call.keywords if k.arg == "history"), None)
            if history is None or isinstance(history, ast.Attribute) and \
                    history.attr.endswith("KEEP_LAST"):
                said = "History and/or depth settings are required" if history is None \
                    else "History set to KEEP_LAST without a depth setting"
                yield Hit(Span(module.path, call.lineno, call.col_offset + 1),
                          f"`QoSProfile()` has no `depth`: rclpy raises "
                          f"InvalidQoSProfileException ('{said}.')", "Add `depth=10`")


_POLICIES = {"history": "a `HistoryPolicy`", "reliability": "a `ReliabilityPolicy`",
             "durability": "a `DurabilityPolicy`", "liveliness": "a `LivelinessPolicy`",
             "depth": "an int"}
"""``QoSProfile`` keywords whose setter asserts an int (or its policy enum, an int too)."""


def _policy_literals(package: Package) -> Iterator[Hit]:
    """``QoSProfile(reliability='reliable')``: a literal other than an int given to a
    policy or the depth, which the profile's setter rejects with an assertion."""
    for module, _, index in installed_trees(package):
        for call in index.calls:
            if index.qualified(call.func) not in PROFILES:
                continue
            for keyword in call.keywords:
                wrong = _wrong_type(keyword.value, _DEPTHS) if keyword.arg in _POLICIES \
                    else None
                if wrong is not None:
                    value = keyword.value
                    yield Hit(Span(module.path, value.lineno, value.col_offset + 1),
                              f"`QoSProfile({keyword.arg}={ast.unparse(value)})` is given a "
                              f"`{wrong}`: its setter asserts {_POLICIES[keyword.arg]} (an "
                              "int), rclpy raises AssertionError",
                              "Use the policy enum, e.g. "
                              "`reliability=ReliabilityPolicy.RELIABLE`, and `depth=10`")


def _negative(value: ast.expr) -> bool:
    """True for a negative ``int`` literal (``-1``)."""
    return isinstance(value, ast.UnaryOp) and isinstance(value.op, ast.USub) and \
        isinstance(value.operand, ast.Constant) and type(value.operand.value) is int and \
        value.operand.value > 0


@rule("PYC018", "invalid-qos-profile", Severity.ERROR,
      fix="Pass the history depth as an int (`10`) or a `QoSProfile`")
def invalid_qos_profile(package: Package) -> Iterator[Hit]:
    """A publisher, subscription, service or client is given a QoS profile rclpy refuses.

    ## What it does
    Checks the `qos_profile` argument (positional or keyword) of `create_publisher`,
    `create_subscription` and `create_lifecycle_publisher` in installed modules that import
    rclpy. Reports a literal that rclpy refuses: a string (`'10'`), a float (`10.0`), bytes,
    a list, tuple, dict or set display, an f-string, and a negative int (`-1`); and any of
    these or an int literal given as `qos_profile=` to `create_service` or `create_client`,
    which take only a `QoSProfile`. Names, attributes, calls (`QoSProfile(depth=10)`,
    `qos_profile_sensor_data`, a depth read from a parameter) and `None` are never reported,
    nor calls with `*args` or `**kwargs`, nor modules defining a method of the same name.
    Also reports `QoSProfile(...)` built with keywords only and no `depth`, its history
    not given or `KEEP_LAST` (`QoSProfile(reliability=ReliabilityPolicy.BEST_EFFORT)`),
    and a `QoSProfile` keyword `history`, `reliability`, `durability`, `liveliness` or
    `depth` given a literal other than an int (`reliability='reliable'`, `depth=10.0`), and
    a predefined profile called like a function (`qos_profile_sensor_data()`: it is a
    `QoSProfile` object, anywhere in the code).

    ## Why is this bad?
    rclpy accepts only a `QoSProfile` or an `int` history depth: anything else raises
    `TypeError: Expected QoSProfile or int, but received <class 'str'>`, a negative depth
    `ValueError`, and the node dies at start-up. Services and clients have no depth shortcut:
    `create_client(Type, 'name', qos_profile=10)` raises `AttributeError`. A depth written as
    a string often means the topic and the depth were swapped. A `QoSProfile` keeping the
    last messages must say how many: without `depth` its constructor raises
    `InvalidQoSProfileException`. Its policies are enums (ints) and its depth an int:
    `QoSProfile(reliability='reliable')` fails an assertion in the setter (checked on
    Jazzy).

    ## Example
    ```python
    self.create_publisher(String, 'chatter', '10')
    self.create_client(Trigger, 'reset', qos_profile=10)
    ```

    ## Use instead
    ```python
    self.create_publisher(String, 'chatter', 10)
    self.create_client(Trigger, 'reset', qos_profile=QoSProfile(depth=10))
    ```
    """
    yield from _service_literals(package)
    yield from _called_presets(package)
    yield from _without_depth(package)
    yield from _policy_literals(package)
    for module, call, method in qos_calls(package):
        parameters = PARAMETERS[method]
        value = argument(call, parameters, "qos_profile")
        if value is None:
            continue
        wrong = _wrong_type(value, _DEPTHS)
        if wrong is None and not _negative(value):
            continue
        topic = argument(call, parameters, "topic")
        swapped = " (are the topic and the depth swapped?)" if isinstance(topic, ast.Constant) \
            and type(topic.value) is int else ""
        problem = f"is a `{wrong}`: rclpy raises `TypeError`" if wrong else \
            "is a negative history depth: rclpy raises `ValueError`"
        yield Hit(Span(module.path, value.lineno, value.col_offset + 1),
                  f"The QoS profile `{ast.unparse(value)}` of `{method}()` {problem}; it takes "
                  f"an int depth or a `QoSProfile`{swapped}")
