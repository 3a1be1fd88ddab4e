"""Which package, node and library names ``pkgtool create`` accepts, and why it refuses others.

colcon puts every package's install folder on ``PYTHONPATH`` for the whole workspace, so a
package named like a Python module (``pytest``, ``numpy``, ``yaml``) is imported instead of
that module by every other package's code and tests.
"""

from __future__ import annotations

import keyword
import sys

from pkgtool.create import CreateError
from pkgtool.lazy_regex import lazy_pattern

# REP 144: lowercase alphanumerics with single underscores between them, a letter first.
NAME = lazy_pattern(r"^[a-z][a-z0-9]*(_[a-z0-9]+)*$")
MAX_NAME = {"package name": 40, "node name": 32, "library name": 32}
"""Longer names do not fit the 99-character lines of ament's flake8 settings."""
_RESERVED = {"test": "it is the folder of the package's tests, which setup.py excludes"}
_TOOLS = {
    "pytest": "`colcon test` runs every package's tests with pytest, and would import this "
              "package instead",
    "setuptools": "colcon builds every ament_python package with setuptools, and would import "
                  "this package instead",
    "pip": "it is Python's installer",
    "wheel": "setuptools builds with the `wheel` module",
    "pluggy": "pytest is built on the `pluggy` module",
    "colcon": "it is the build tool's name",
}
"""Python modules the build and test tools import, beyond those with a rosdep key."""


def python_module_reason(name: str) -> str | None:
    """Why ``name`` may not be a package name because of a Python module, or None."""
    from pkgtool.knowledge.rosdistro import keys_for_import

    if name in _TOOLS:
        return f"it is the name of a Python module: {_TOOLS[name]}"
    keys = [key for key in keys_for_import(name) if not key.endswith("-pip")]
    if keys:  # a module only pip installs is too rare to forbid a name (`control`, `motor`)
        return (f"it is the name of a well-known Python module (rosdep key `{keys[0]}`): the "
                "package would be imported instead of it by every package of the workspace")
    return None


def ros_package_reason(name: str) -> str | None:
    """Why ``name`` may not be a package name because a released ROS package has it, or None."""
    from pkgtool.knowledge.rosdistro import DEFAULT_DISTRO, is_released_package

    if not is_released_package(name, DEFAULT_DISTRO):
        return None
    return (f"a ROS package of that name is released for {DEFAULT_DISTRO}: next to it (installed "
            "or in the workspace) colcon, rosdep and Python imports would take one for the "
            "other. Pick a name of your own (a prefix such as `my_` does it)")


def check_name(value: str, what: str) -> str:
    """``value`` if it is a valid REP 144 name usable as a Python module, else CreateError."""
    problem = None
    if not NAME.match(value):
        problem = ("use only lowercase letters, digits and single underscores, starting with a "
                   "letter (REP 144)")
    elif not 2 <= len(value) <= MAX_NAME[what]:
        problem = (f"use 2 to {MAX_NAME[what]} characters (longer names do not fit ament's "
                   "99-character lines)")
    elif keyword.iskeyword(value):
        problem = "it is a Python keyword"
    elif value in sys.stdlib_module_names:
        problem = "it would shadow the standard library module of that name"
    elif value in _RESERVED:
        problem = _RESERVED[value]
    elif what == "package name":
        problem = python_module_reason(value) or ros_package_reason(value)
    if problem:
        raise CreateError(f"Invalid {what} `{value}`: {problem}.")
    return value
