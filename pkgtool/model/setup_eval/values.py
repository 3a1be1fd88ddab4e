"""Values of the setup.py evaluator: plain data tagged with the expression that produced it."""

from __future__ import annotations

from pathlib import PurePosixPath
from typing import Any

from pkgtool.model.span import Span, Unresolved
from pkgtool.records import field, record


@record
class GlobOrigin:
    """A glob call: its pattern (package-relative) and where it was written."""

    pattern: str
    span: Span


class Str(str):
    """A string with the span of the expression that made it; ``glob`` when a glob matched it."""

    span: Span | None = None
    glob: GlobOrigin | None = None


class Lst(list):  # type: ignore[type-arg]
    """A list with its span and the globs whose (possibly empty) results it holds."""

    span: Span | None = None
    origins: tuple[GlobOrigin, ...] = ()


class Tup(tuple):  # type: ignore[type-arg]
    """A tuple with its span and the globs whose results it holds."""

    span: Span | None = None
    origins: tuple[GlobOrigin, ...] = ()


class Dct(dict):  # type: ignore[type-arg]
    """A dict with the span of the expression that made it."""

    span: Span | None = None


class Found(Lst):
    """The result of ``find_packages``/``find_namespace_packages`` with the finder's arguments."""

    kind: str = "find_packages"
    where: str = "."
    include: tuple[str, ...] = ("*",)
    exclude: tuple[str, ...] = ()


@record
class PathValue:
    """A ``pathlib`` path, relative to the package root; ``glob`` when a glob produced it."""

    pure: PurePosixPath
    glob: GlobOrigin | None = None

    def __str__(self) -> str:
        return self.pure.as_posix()


@record
class Builtin:
    """A known module or function, by qualified name (``os.path.join``, ``glob``)."""

    name: str


@record
class BoundMethod:
    """``value.name`` where ``value`` is evaluated data and ``name`` an allowed method."""

    value: Any
    name: str


@record
class Opaque:
    """A name bound to something the evaluator refused to compute."""

    unresolved: Unresolved


@record
class UserFunc:
    """A function defined in setup.py: its ``ast.FunctionDef`` and the scope it was defined in."""

    node: Any
    scope: Any = field(compare=False)


class NotStatic(Exception):
    """Raised when an expression cannot be evaluated; carries the offending source and span."""

    def __init__(self, unresolved: Unresolved) -> None:
        super().__init__(unresolved.source)
        self.unresolved = unresolved


class OutOfBudget(NotStatic):
    """The evaluation took too many steps or built too large a value."""


def tagged_str(value: str, span: Span | None, glob: GlobOrigin | None = None) -> Str:
    """``value`` as a :class:`Str` carrying ``span`` (and ``glob``)."""
    result = Str(value)
    result.span = span
    result.glob = glob
    return result


def tagged_list(items: Any, span: Span | None, origins: tuple[GlobOrigin, ...] = ()) -> Lst:
    """``items`` as a :class:`Lst` carrying ``span`` and glob ``origins``."""
    result = Lst(items)
    result.span = span
    result.origins = origins
    return result


def tagged_tuple(items: Any, span: Span | None, origins: tuple[GlobOrigin, ...] = ()) -> Tup:
    """``items`` as a :class:`Tup` carrying ``span`` and glob ``origins``."""
    result = Tup(items)
    result.span = span
    result.origins = origins
    return result


def tagged_dict(items: Any, span: Span | None) -> Dct:
    """``items`` as a :class:`Dct` carrying ``span``."""
    result = Dct(items)
    result.span = span
    return result


def origins_of(*values: object) -> tuple[GlobOrigin, ...]:
    """The glob origins carried by ``values`` (containers), without duplicates."""
    found: list[GlobOrigin] = []
    for value in values:
        for origin in getattr(value, "origins", ()):
            if origin not in found:
                found.append(origin)
    return tuple(found)


PRIMITIVES = (str, int, float, bool, type(None))


def plain(value: object, where: Unresolved) -> object:
    """Convert evaluated data to plain Python data (lists become tuples); else NotStatic."""
    if isinstance(value, PRIMITIVES):
        return value if type(value) is not Str else str(value)
    if isinstance(value, PathValue):
        return str(value)
    if isinstance(value, (list, tuple)):
        return tuple(plain(item, where) for item in value)
    if isinstance(value, (set, frozenset)):
        return tuple(sorted((plain(item, where) for item in value), key=repr))
    if isinstance(value, dict):
        return {plain(k, where): plain(v, where) for k, v in value.items()}
    raise NotStatic(where)
