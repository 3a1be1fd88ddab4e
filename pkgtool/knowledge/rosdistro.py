"""What ros/rosdistro says: released ROS packages, rosdep keys, and which keys provide an import.

Lookups over the generated tables in ``data/`` (see
:mod:`pkgtool.knowledge.generate_rosdistro`); each table is read on its first use. Every
function takes the target ``distro`` (one of :data:`DISTROS`, default :data:`DEFAULT_DISTRO`).
"""

from __future__ import annotations

import difflib
from functools import cache

from pkgtool.knowledge.tables import DISTROS, FLAGS, read

__all__ = ["DEFAULT_DISTRO", "DISTROS", "PYTHON_VERSIONS", "close_names", "is_known_dependency",
           "is_released_package", "is_rosdep_key", "key_resolves", "keys_for_import",
           "released_packages", "rosdep_keys", "source_commit"]

DEFAULT_DISTRO = "jazzy"
PYTHON_VERSIONS = {"humble": "3.10", "jazzy": "3.12", "kilted": "3.12", "rolling": "3.12"}
"""The Python of each distribution's primary platform (Ubuntu's ``python3``)."""


def _check(distro: str) -> str:
    if distro not in FLAGS:
        raise ValueError(f"unknown ROS distribution {distro!r}; known: {', '.join(DISTROS)}")
    return FLAGS[distro]


def _flags(table: str) -> dict[str, str]:
    return read(table).flags


@cache
def released_packages(distro: str = DEFAULT_DISTRO) -> frozenset[str]:
    """Every ROS package ``distro`` releases."""
    flag = _check(distro)
    return frozenset(name for name, flags in _flags("ros_packages").items() if flag in flags)


def is_released_package(name: str, distro: str = DEFAULT_DISTRO) -> bool:
    """True when ``name`` is a ROS package released for ``distro``."""
    return _check(distro) in _flags("ros_packages").get(name, "")


def rosdep_keys() -> frozenset[str]:
    """Every key of rosdep's base.yaml and python.yaml."""
    return frozenset(_flags("rosdep_keys"))


def is_rosdep_key(name: str) -> bool:
    """True when ``name`` is a key of rosdep's base.yaml or python.yaml."""
    return name in _flags("rosdep_keys")


def key_resolves(key: str, distro: str = DEFAULT_DISTRO) -> bool:
    """True when rosdep ``key`` installs something on ``distro``'s Ubuntu release."""
    return _check(distro) in _flags("rosdep_keys").get(key, "")


def is_known_dependency(name: str, distro: str = DEFAULT_DISTRO) -> bool:
    """True when ``name`` is a ROS package released for ``distro`` or a rosdep key."""
    return is_released_package(name, distro) or is_rosdep_key(name)


def keys_for_import(top_level: str, distro: str = DEFAULT_DISTRO) -> tuple[str, ...]:
    """The rosdep keys that install the top-level module ``top_level``, best first.

    The first key is one that resolves on ``distro`` when any does; empty when rosdep has no
    key for the module. Module names are matched ignoring case, as Debian's names do.
    """
    keys = read("python_imports").values.get(top_level.lower(), "").split()
    usable = [k for k in keys if key_resolves(k, distro)]
    return tuple(usable + [k for k in keys if k not in usable])


def close_names(name: str, distro: str = DEFAULT_DISTRO, *, extra: frozenset[str] = frozenset(),
                limit: int = 1) -> list[str]:
    """Released packages, rosdep keys and ``extra`` names spelled like ``name`` (near misses)."""
    candidates = _candidates(distro) | extra
    return difflib.get_close_matches(name, candidates, n=limit, cutoff=0.85)


@cache
def _candidates(distro: str) -> frozenset[str]:
    return released_packages(distro) | rosdep_keys()


def source_commit() -> str:
    """The ros/rosdistro commit the tables were generated from."""
    return read("ros_packages").source.split()[-1]
