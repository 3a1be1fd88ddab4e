"""Remember what is derived from a package, so that rules sharing a derivation compute it once.

Packages are immutable, so a result stays valid for the package object it was computed from.
The cache holds the last few packages by identity (a workspace is linted one package at a
time), never by equality, and keeps them alive only while they are among those few.
"""

from __future__ import annotations

import functools
from collections import OrderedDict
from collections.abc import Callable
from typing import TypeVar

P = TypeVar("P")
R = TypeVar("R")
_KEEP = 4


def per_package(function: Callable[[P], R]) -> Callable[[P], R]:
    """Cache ``function(package)`` per package object (identity), for the last few packages."""
    cache: OrderedDict[int, tuple[P, R]] = OrderedDict()

    @functools.wraps(function)
    def cached(package: P) -> R:
        key = id(package)
        hit = cache.get(key)
        if hit is not None and hit[0] is package:
            return hit[1]
        result = function(package)
        cache[key] = (package, result)
        if len(cache) > _KEEP:
            cache.popitem(last=False)
        return result

    return cached
