"""What ros/rosdistro says: released ROS packages, rosdep keys, and which keys provide an import.

Lookups over the generated tables in ``data/`` (see
:mod:`pkgtool.knowledge.generate_rosdistro`); each table is read on its first use. Every
function takes the target ``distro`` (one of :data:`DISTROS`, default :data:`DEFAULT_DISTRO`).
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable
from functools import cache, lru_cache

from pkgtool.knowledge.tables import DEFAULT_DISTRO, DISTROS, FLAGS, read
from pkgtool.lazy_regex import lazy_pattern

__all__ = ["DEFAULT_DISTRO", "DISTROS", "PYTHON_VERSIONS", "alternative_key", "close_names",
           "is_known_dependency", "is_released_package", "is_rosdep_key", "key_resolves",
           "key_of_ubuntu_package", "keys_for_import", "modules_of_key", "released_packages",
           "rosdep_keys",
           "source_commit", "stdlib_modules", "any_stdlib_module", "stdlib_versions"]

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


def released_executables(package: str, distro: str = DEFAULT_DISTRO) -> frozenset[str] | None:
    """The executables a common released package installs into ``lib/<package>`` on
    ``distro`` (``data/released_executables.txt``), or None when the table does not know."""
    table = read("released_executables")
    key = f"{distro}:{package}"
    return frozenset(table.values.get(key, "").split()) if key in table.flags else None


def released_installers(executable: str, distro: str = DEFAULT_DISTRO) -> tuple[str, ...]:
    """The common released packages that install ``executable`` on ``distro`` (see
    :func:`released_executables`)."""
    prefix = f"{distro}:"
    return tuple(sorted(key[len(prefix):] for key, names in
                        read("released_executables").values.items()
                        if key.startswith(prefix) and executable in names.split()))


def rosdep_keys() -> frozenset[str]:
    """Every key of rosdep's base.yaml and python.yaml."""
    return frozenset(_flags("rosdep_keys"))


def is_rosdep_key(name: str) -> bool:
    """True when ``name`` is a key of rosdep's base.yaml or python.yaml."""
    return name in _flags("rosdep_keys")


def key_of_ubuntu_package(name: str) -> str | None:
    """The rosdep key that installs the Ubuntu package ``name`` (no key itself): the one key
    naming it (``libyaml-cpp-dev``: ``yaml-cpp``), or the key it is with ``-dev`` added when
    that key installs a development package of its name (``libpcap-dev``: ``libpcap``, which
    installs ``libpcap0.8-dev``, the package the alias stands for); else None."""
    if is_rosdep_key(name):
        return None
    known = read("ubuntu_packages").values.get(name)
    if known:
        return known
    bare = name.removesuffix("-dev")
    return bare if bare != name and any(
        other.startswith(bare) and other.endswith("-dev")
        for other in _ubuntu_packages_by_key().get(bare, ())) else None


@cache
def _ubuntu_packages_by_key() -> dict[str, tuple[str, ...]]:
    found: dict[str, list[str]] = {}
    for name, key in read("ubuntu_packages").values.items():
        found.setdefault(key, []).append(name)
    return {key: tuple(names) for key, names in found.items()}


def key_resolves(key: str, distro: str = DEFAULT_DISTRO) -> bool:
    """True when rosdep ``key`` installs something on ``distro``'s Ubuntu release."""
    return _check(distro) in _flags("rosdep_keys").get(key, "")


def is_known_dependency(name: str, distro: str = DEFAULT_DISTRO) -> bool:
    """True when ``name`` is a ROS package released for ``distro`` or a rosdep key."""
    return is_released_package(name, distro) or is_rosdep_key(name)


@lru_cache(maxsize=4096)
def keys_for_import(top_level: str, distro: str = DEFAULT_DISTRO) -> tuple[str, ...]:
    """The rosdep keys that install the top-level module ``top_level``, best first.

    The first key is one that resolves on ``distro`` when any does; empty when rosdep has no
    key for the module. Module names are matched ignoring case, as Debian's names do, but
    for the two Adafruit families (:func:`_other_adafruit_family`).
    """
    keys = [k for k in read("python_imports").values.get(top_level.lower(), "").split()
            if not _other_adafruit_family(top_level, k)]
    usable = [k for k in keys if key_resolves(k, distro)]
    return tuple(usable + [k for k in keys if k not in usable])


def _other_adafruit_family(top_level: str, key: str) -> bool:
    """True for a key of the other Adafruit family than the import's: CircuitPython
    libraries are imported in lower case (``adafruit_pca9685``, ``adafruit_servokit``); the
    older Adafruit_Python libraries, whose keys python_imports.txt lists apart (read from the
    distributions they install), are imported capitalised (``Adafruit_PCA9685``). The table
    matches names ignoring case, which would offer one family's key for the other's import."""
    if not top_level.lower().startswith("adafruit_") or "adafruit" not in key:
        return False
    return (key in _older_adafruit_keys()) == top_level.startswith("adafruit_")


@cache
def _older_adafruit_keys() -> frozenset[str]:
    """The keys installing the older Adafruit_Python libraries."""
    table = read("python_imports")
    return frozenset(key for key, flags in table.flags.items() if flags == "older-adafruit")


@cache
def _modules_by_key() -> dict[str, tuple[str, ...]]:
    found: dict[str, list[str]] = {}
    for module, keys in read("python_imports").values.items():
        for key in keys.split():
            found.setdefault(key, []).append(module)
    return {key: tuple(modules) for key, modules in found.items()}


def modules_of_key(key: str) -> tuple[str, ...]:
    """The top-level modules (lower case) that rosdep ``key`` installs, as far as known."""
    return _modules_by_key().get(key, ())


def alternative_key(key: str, distro: str = DEFAULT_DISTRO) -> str | None:
    """Another key installing a module of ``key`` that resolves on ``distro``, if any."""
    for module in modules_of_key(key):
        best = keys_for_import(module, distro)
        if best and best[0] != key and key_resolves(best[0], distro):
            return best[0]
    return None


def close_names(name: str, distro: str = DEFAULT_DISTRO, *, extra: frozenset[str] = frozenset(),
                limit: int = 1) -> list[str]:
    """Released packages, rosdep keys and ``extra`` names spelled like ``name``: near misses
    that are also a typo away (one edit for names under 14 characters, else two; a swap of
    neighbours is one), so that a different package with a similar name is not offered."""
    lengths = range(len(name) - 2, len(name) + 3)  # a typo changes the length by two at most
    by_length = _candidates_by_length(distro)
    candidates = dict.fromkeys([*(c for length in lengths for c in by_length.get(length, ())),
                                *sorted(c for c in extra if len(c) in lengths)])
    similar = difflib.get_close_matches(name, candidates, n=max(limit, 20), cutoff=0.7)
    return [c for c in similar if is_typo(name, c)][:limit]


def is_typo(word: str, other: str) -> bool:
    """True when ``other`` is a typo away from ``word``: one edit for words under 14
    characters, else two (insert, delete, replace; a swap of neighbours is one)."""
    budget = 1 if len(word) < 14 else 2
    return typo_distance(word, other, budget) <= budget


def digits_differ(first: str, second: str) -> bool:
    """True when the names differ in a digit (``turtlebot3``, ``turtlebot4``; ``robot1/scan``,
    ``robot2/scan``): numbered names are meant to differ, never a typo of each other."""
    return sorted(c for c in first if c.isdigit()) != sorted(c for c in second if c.isdigit())


def typo_of(word: str, choices: Iterable[str]) -> str | None:
    """The one of ``choices`` a typo away from ``word`` (:func:`is_typo`), or None when none
    or several are."""
    found = [c for c in set(choices) if c != word and is_typo(word, c)]
    return found[0] if len(found) == 1 else None


def typo_distance(first: str, second: str, budget: int) -> int:
    """Edits (insert, delete, replace, swap of neighbours) from ``first`` to ``second``;
    anything above ``budget`` is reported as ``budget + 1``."""
    if abs(len(first) - len(second)) > budget:
        return budget + 1
    before: list[int] = []
    row = list(range(len(second) + 1))
    for i, a in enumerate(first, 1):
        current = [i] + [0] * len(second)
        for j, b in enumerate(second, 1):
            current[j] = min(row[j] + 1, current[j - 1] + 1, row[j - 1] + (a != b))
            if i > 1 and j > 1 and a == second[j - 2] and first[i - 2] == b:
                current[j] = min(current[j], before[j - 2] + 1)
        before, row = row, current
    return min(row[-1], budget + 1)


@cache
def _candidates(distro: str) -> frozenset[str]:
    return released_packages(distro) | rosdep_keys()


@cache
def _candidates_by_length(distro: str) -> dict[int, tuple[str, ...]]:
    """:func:`_candidates` by length, each group sorted (the order ties keep)."""
    found: dict[int, list[str]] = {}
    for name in sorted(_candidates(distro)):
        found.setdefault(len(name), []).append(name)
    return {length: tuple(names) for length, names in found.items()}


_NUMBERS = lazy_pattern(r"[0-9]+")


def numbered_variants(name: str, distro: str = DEFAULT_DISTRO) -> list[str]:
    """Released packages and rosdep keys that differ from ``name`` in its numbers only
    (``gz-transport12`` and ``gz-transport13`` for ``gz-transport7``), sorted."""
    if not _NUMBERS.search(name):
        return []
    shape = _NUMBERS.sub("#", name)
    return sorted(c for c in _by_shape(distro).get(shape, ()) if c != name)


@cache
def _by_shape(distro: str) -> dict[str, tuple[str, ...]]:
    """The candidates holding numbers, by their name with each number written ``#``."""
    found: dict[str, list[str]] = {}
    for candidate in _candidates(distro):
        if _NUMBERS.search(candidate):
            found.setdefault(_NUMBERS.sub("#", candidate), []).append(candidate)
    return {shape: tuple(names) for shape, names in found.items()}


def source_commit() -> str:
    """The ros/rosdistro commit the tables were generated from."""
    return read("ros_packages").source.split()[-1]


def _version_flag(version: str) -> str:
    return format(int(version.split(".")[1]), "x")


@cache
def stdlib_modules(distro: str = DEFAULT_DISTRO) -> frozenset[str]:
    """Top-level standard library modules of ``distro``'s Python (``data/stdlib.txt``)."""
    flag = _version_flag(PYTHON_VERSIONS[distro])
    return frozenset(name for name, flags in _flags("stdlib").items() if flag in flags)


STDLIB_VERSIONS = tuple(f"3.{minor}" for minor in range(6, 15))
"""The Python 3 versions whose standard library ``data/stdlib.txt`` lists."""


@cache
def any_stdlib_module() -> frozenset[str]:
    """Top-level modules in the standard library of any Python 3 from 3.6 to 3.14."""
    return frozenset(_flags("stdlib"))


def stdlib_versions(module: str) -> tuple[str, ...]:
    """The Python 3 versions (3.6-3.14) whose standard library has ``module``."""
    flags = _flags("stdlib").get(module, "")
    return tuple(v for v in STDLIB_VERSIONS if _version_flag(v) in flags)
