"""REP 149 ``condition`` attributes, evaluated for a target distribution.

The grammar is catkin_pkg's: ``$VAR`` and literal words compared with ``==`` or ``!=``,
combined with ``and``/``or`` and parentheses; an unset variable is the empty string. For a ROS 2
target ``ROS_VERSION`` is ``2``, ``ROS_PYTHON_VERSION`` ``3`` and ``ROS_DISTRO`` the distribution.
"""

from __future__ import annotations

from pkgtool.lazy_regex import lazy_pattern

_TOKEN = lazy_pattern(r"\s*(\$?[\w.-]+|==|!=|\(|\)|\S)")


def environment(distro: str) -> dict[str, str]:
    """The variables ``rosdep`` and colcon set for a ROS 2 ``distro``."""
    return {"ROS_VERSION": "2", "ROS_PYTHON_VERSION": "3", "ROS_DISTRO": distro}


def applies(condition: str | None, distro: str) -> bool:
    """True when a tag with this ``condition`` is used for a ROS 2 ``distro``: it has none, or
    it is true (one that is false or not understood leaves the tag out)."""
    return condition is None or evaluate(condition, environment(distro)) is True


def under_ros2(condition: str | None) -> bool | None:
    """Whether a tag with this ``condition`` is used by every ROS 2 distribution: True without
    one, None when the value depends on the distribution (``$ROS_DISTRO``) or is not a valid
    condition. Catkin and ament build a package declaring ``condition="$ROS_VERSION == 1"``
    and ``== 2`` tags under ROS 1 and ROS 2 alike."""
    if condition is None:
        return True
    if "ROS_DISTRO" in condition:
        return None
    return evaluate(condition, {"ROS_VERSION": "2", "ROS_PYTHON_VERSION": "3"})


def evaluate(condition: str, variables: dict[str, str]) -> bool | None:
    """The value of ``condition``; None when it is not a valid condition."""
    tokens = _TOKEN.findall(condition)
    try:
        value, rest = _or(tokens, variables)
    except (IndexError, ValueError):
        return None
    return value if not rest else None


Tokens = list[str]


def _or(tokens: Tokens, env: dict[str, str]) -> tuple[bool, Tokens]:
    return _chain(tokens, env, "or")


def _and(tokens: Tokens, env: dict[str, str]) -> tuple[bool, Tokens]:
    return _chain(tokens, env, "and")


def _chain(tokens: Tokens, env: dict[str, str], word: str) -> tuple[bool, Tokens]:
    """Operands joined by ``word``; ``and`` binds tighter than ``or``."""
    operand = _and if word == "or" else _comparison
    value, tokens = operand(tokens, env)
    while tokens and tokens[0] == word:
        right, tokens = operand(tokens[1:], env)
        value = (value or right) if word == "or" else (value and right)
    return value, tokens


def _comparison(tokens: Tokens, env: dict[str, str]) -> tuple[bool, Tokens]:
    if tokens[0] == "(":
        value, rest = _or(tokens[1:], env)
        if not rest or rest[0] != ")":
            raise ValueError("unbalanced parenthesis")
        return value, rest[1:]
    left, operator, right = tokens[0], tokens[1], tokens[2]
    if operator not in ("==", "!="):
        raise ValueError(f"unknown operator {operator}")
    equal = _value(left, env) == _value(right, env)
    return equal if operator == "==" else not equal, tokens[3:]


def _value(token: str, env: dict[str, str]) -> str:
    if token in ("(", ")", "==", "!=", "and", "or"):
        raise ValueError(f"unexpected {token}")
    return env.get(token[1:], "") if token.startswith("$") else token
