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
    return per_object(_KEEP)(function)


def per_object(keep: int) -> Callable[[Callable[[P], R]], Callable[[P], R]]:
    """Cache ``function(obj)`` per object identity for the last ``keep`` objects (any type,
    e.g. a syntax tree shared read-only by the model and the rules)."""

    def decorate(function: Callable[[P], R]) -> Callable[[P], R]:
        cache: OrderedDict[int, tuple[P, R]] = OrderedDict()

        @functools.wraps(function)
        def cached(obj: P) -> R:
            key = id(obj)
            hit = cache.get(key)
            if hit is not None and hit[0] is obj:
                return hit[1]
            result = function(obj)
            cache[key] = (obj, result)
            if len(cache) > keep:
                cache.popitem(last=False)
            return result

        return cached

    return decorate
