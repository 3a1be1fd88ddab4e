"""The Python version a project's pyproject.toml says it runs on, when it says so.

ROS 2 distributions fix their Python (Humble 3.10, Jazzy 3.12), but a workspace built another
way (pixi with RoboStack, a virtual environment) may pin a newer one, and what a line does can
depend on it: from Python 3.14 annotations are evaluated only when read (PEP 649), so a class
named in its own methods' annotations is no NameError there. Read, in this order: `[project]
requires-python` (its lowest version), `[tool.mypy] python_version`, `[tool.ruff]
target-version` (`py314`), and a `python` dependency of a pixi table (`python = "3.14*"`).
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from typing import Any

_VERSION = re.compile(r"(?<![\d.])(3)\.(\d+)")
_RUFF = re.compile(r"py3(\d+)")


def declared_python(text: str) -> tuple[int, int] | None:
    """The (major, minor) Python version the pyproject.toml ``text`` declares, or None (also
    for a file that does not parse)."""
    if "python" not in text and "target-version" not in text:
        return None
    from pkgtool.compat import tomllib

    try:
        table = tomllib.loads(text)
    except tomllib.TOMLDecodeError:
        return None
    tool = _table(table.get("tool"))
    candidates = (_lowest(_table(table.get("project")).get("requires-python")),
                  _lowest(_table(tool.get("mypy")).get("python_version")),
                  _ruff(_table(tool.get("ruff")).get("target-version")),
                  _lowest(_pixi_python(_table(tool.get("pixi")))))
    return next((found for found in candidates if found is not None), None)


def _table(value: Any) -> Mapping[str, Any]:
    return value if isinstance(value, dict) else {}


def _lowest(value: Any) -> tuple[int, int] | None:
    """The lowest ``3.x`` a version or specifier (``>=3.14``, ``3.14*``) names."""
    found = [(3, int(minor)) for _, minor in _VERSION.findall(value)] \
        if isinstance(value, str) else []
    return min(found) if found else None


def _ruff(value: Any) -> tuple[int, int] | None:
    found = _RUFF.fullmatch(value) if isinstance(value, str) else None
    return (3, int(found.group(1))) if found else None


def _pixi_python(pixi: Mapping[str, Any]) -> Any:
    """The ``python`` of a pixi ``dependencies`` table, at any depth (``[tool.pixi.feature.
    ros.dependencies]``)."""
    for key, value in pixi.items():
        if not isinstance(value, dict):
            continue
        if key == "dependencies" and "python" in value:
            return value["python"]
        found = _pixi_python(value)
        if found is not None:
            return found
    return None
