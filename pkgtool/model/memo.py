"""Remember what is derived from a package, so that rules sharing a derivation compute it once.

Packages are immutable, so a result stays valid for the package object it was computed from.
The cache holds the last few packages by identity (a workspace is linted one package at a
time), never by equality, and keeps them alive only while they are among those few. Facts of
syntax trees (:func:`per_tree`) stay until the package is done, however many modules it has.
"""

from __future__ import annotations

import functools
from collections import OrderedDict
from collections.abc import Callable
from typing import TypeVar

P = TypeVar("P")
R = TypeVar("R")
_KEEP = 4
_TREE_ENTRIES = 200_000
"""How many results the per-tree caches hold together before they start over: far more than
the largest package makes (callers that never call :func:`forget_tree_facts` stay bounded)."""
_NOTHING = object()
_tree_caches: list[dict[int, tuple[object, object]]] = []


def per_package(function: Callable[[P], R]) -> Callable[[P], R]:
    """Cache ``function(package)`` per package object (identity), for the last few packages."""
    return per_object(_KEEP)(function)


def per_object(keep: int) -> Callable[[Callable[[P], R]], Callable[[P], R]]:
    """Cache ``function(obj)`` per object identity for the last ``keep`` objects (any type,
    e.g. a syntax tree shared read-only by the model and the rules)."""

    def decorate(function: Callable[[P], R]) -> Callable[[P], R]:
        cache: OrderedDict[int, tuple[P, R]] = OrderedDict()
        last: list[object] = [_NOTHING, None]  # the object asked for last, its result: most
        # calls ask for the same package again, and this test is cheaper than the look-up

        @functools.wraps(function)
        def cached(obj: P) -> R:
            if last[0] is obj:
                return last[1]  # type: ignore[return-value]
            key = id(obj)
            hit = cache.get(key)
            if hit is None or hit[0] is not obj:
                hit = (obj, function(obj))
                cache[key] = hit
                if len(cache) > keep:
                    cache.popitem(last=False)
            last[0], last[1] = hit
            return hit[1]

        return cached

    return decorate


def per_tree(function: Callable[[P], R]) -> Callable[[P], R]:
    """Cache ``function(obj)`` per object identity (a syntax tree, a part of one or its index)
    until :func:`forget_tree_facts`, which the linter calls when done with a package: a rule
    looking at every module of a package of thousands finds every tree's facts still there."""
    cache: dict[int, tuple[object, object]] = {}
    _tree_caches.append(cache)

    @functools.wraps(function)
    def cached(obj: P) -> R:
        hit = cache.get(id(obj))
        if hit is not None and hit[0] is obj:
            return hit[1]  # type: ignore[return-value]
        result = function(obj)
        if len(cache) >= _TREE_ENTRIES:
            cache.clear()
        cache[id(obj)] = (obj, result)
        return result

    return cached


def forget_tree_facts() -> None:
    """Drop every :func:`per_tree` result (the trees of the package just checked)."""
    for cache in _tree_caches:
        cache.clear()
