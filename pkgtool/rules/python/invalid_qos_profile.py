"""PYC018: a publisher or subscription given a literal that is no QoS profile (``'10'``)."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import PARAMETERS, argument, qos_calls
from pkgtool.rules.registry import rule

_DISPLAYS = {ast.List: "list", ast.Tuple: "tuple", ast.Dict: "dict", ast.Set: "set",
             ast.JoinedStr: "str"}
"""Literal displays and the type they build."""


def _wrong_type(value: ast.expr) -> str | None:
    """Why the literal ``value`` is neither an ``int`` depth nor a ``QoSProfile``, if it is
    one: its type (``str``, ``float``, ...); None for anything else, ``None`` included."""
    if isinstance(value, ast.Constant):
        literal = value.value
        wrong = not isinstance(literal, int) and literal is not None and literal is not ...
        return type(literal).__name__ if wrong else None
    return _DISPLAYS.get(type(value))


def _negative(value: ast.expr) -> bool:
    """True for a negative ``int`` literal (``-1``)."""
    return isinstance(value, ast.UnaryOp) and isinstance(value.op, ast.USub) and \
        isinstance(value.operand, ast.Constant) and type(value.operand.value) is int and \
        value.operand.value > 0


@rule("PYC018", "invalid-qos-profile", Severity.ERROR,
      fix="Pass the history depth as an int (`10`) or a `QoSProfile`")
def invalid_qos_profile(package: Package) -> Iterator[Hit]:
    """A publisher or subscription is given a QoS profile that is a string or float literal.

    ## What it does
    Checks the `qos_profile` argument (positional or keyword) of `create_publisher`,
    `create_subscription` and `create_lifecycle_publisher` in installed modules that import
    rclpy. Reports a literal that rclpy refuses: a string (`'10'`), a float (`10.0`), bytes,
    a list, tuple, dict or set display, an f-string, and a negative int (`-1`). Names,
    attributes, calls (`QoSProfile(depth=10)`, `qos_profile_sensor_data`, a depth read from a
    parameter) and `None` are never reported, nor calls with `*args` or `**kwargs`, nor
    modules defining a method of the same name.

    ## Why is this bad?
    rclpy accepts only a `QoSProfile` or an `int` history depth: anything else raises
    `TypeError: Expected QoSProfile or int, but received <class 'str'>`, a negative depth
    `ValueError`, and the node dies at start-up. A depth written as a string often means
    the topic and the depth were swapped.

    ## Example
    ```python
    self.create_publisher(String, 'chatter', '10')
    ```

    ## Use instead
    ```python
    self.create_publisher(String, 'chatter', 10)
    ```
    """
    for module, call, method in qos_calls(package):
        parameters = PARAMETERS[method]
        value = argument(call, parameters, "qos_profile")
        if value is None:
            continue
        wrong = _wrong_type(value)
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
