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

_SERVICES = ("create_service", "create_client")
_VALUES = frozenset({"NoneType", "ellipsis"})
"""Literals never reported: ``None`` (the default of some wrappers) and ``...``."""
_DEPTHS = frozenset({"int", "bool"})
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

    ## Why is this bad?
    rclpy accepts only a `QoSProfile` or an `int` history depth: anything else raises
    `TypeError: Expected QoSProfile or int, but received <class 'str'>`, a negative depth
    `ValueError`, and the node dies at start-up. Services and clients have no depth shortcut:
    `create_client(Type, 'name', qos_profile=10)` raises `AttributeError`. A depth written as
    a string often means the topic and the depth were swapped.

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
