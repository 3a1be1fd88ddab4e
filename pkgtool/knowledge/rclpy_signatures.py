"""The keywords rclpy's most used calls take (``data/rclpy_signatures.txt``, Humble to
Rolling): methods by name, functions and constructors by the dotted name code calls them by."""

from __future__ import annotations

from functools import cache

from pkgtool.knowledge.tables import read

ALIASES = {"rclpy.action.server.ActionServer": "rclpy.action.ActionServer",
           "rclpy.action.client.ActionClient": "rclpy.action.ActionClient"}
"""Other names the constructors of the table are imported by."""


@cache
def _table() -> dict[str, frozenset[str]]:
    table = read("rclpy_signatures")
    return {name: frozenset(values.split()) for name, values in table.values.items()}


def parameters_of(call: str) -> frozenset[str] | None:
    """The parameter names of ``call`` (``**`` when it takes any keyword), None when the table
    does not hold it."""
    return _table().get(ALIASES.get(call, call))


def methods() -> frozenset[str]:
    """The method names the table holds (no dot in them)."""
    return frozenset(name for name in _table() if "." not in name)
