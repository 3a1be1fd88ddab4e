"""``@record``: immutable value classes, as ``@dataclass(frozen=True, slots=True)``, made cheaply.

Every model object, finding and result is such a class, and linting one package defines about
seventy of them at start-up. On CPython before 3.13 ``dataclass`` compiles six methods from
source for each frozen class and importing ``dataclasses`` imports ``inspect``: measured, a
third of a one-package lint (88 ms of 265 ms). A record compiles one method, ``__init__``,
when its first instance is made;
equality, hashing, ordering, ``repr``, the frozen ``__setattr__``/``__delattr__`` and
pickling are shared functions reading the fields through one ``operator.attrgetter`` per
class. They behave as dataclass's: assigning or deleting an attribute raises
:class:`FrozenInstanceError`; an instance equals (and, with ``order=True``, orders against)
only an instance of the very same class, on the fields with ``compare=True``, which are also
what it hashes; ``repr`` shows the fields with ``repr=True``; a field's default factory is
called for each instance; ``__post_init__`` runs after ``__init__`` when the class has one.

:func:`fields`, :func:`replace` and :func:`asdict` are the dataclasses functions of the same
names for records.
"""

from __future__ import annotations

from operator import attrgetter
from typing import Any, Callable, TypeVar, overload

T = TypeVar("T", bound=type)
R = TypeVar("R")

try:
    from typing import dataclass_transform
except ImportError:  # Python 3.10; only type checkers read it
    def dataclass_transform(**_: Any) -> Callable[[R], R]:  # type: ignore[no-redef]
        """Python 3.11's marker of dataclass-like decorators, doing nothing here."""
        return lambda function: function


class FrozenInstanceError(AttributeError):
    """Raised on assigning to or deleting a field of a record."""


class _Missing:
    """No default given; as an argument's default, the field's factory makes the value."""

    def __repr__(self) -> str:
        return "<factory>"


MISSING: Any = _Missing()


class Field:
    """A field of a record: its name, default or default factory, and whether it is compared
    (and hashed) and shown by ``repr``."""

    __slots__ = ("name", "default", "default_factory", "compare", "repr")

    def __init__(self, default: Any = MISSING, default_factory: Any = MISSING,
                 compare: bool = True, repr: bool = True) -> None:  # noqa: A002 - as dataclasses
        self.name = ""
        self.default = default
        self.default_factory = default_factory
        self.compare = compare
        self.repr = repr


def field(*, default: Any = MISSING, default_factory: Callable[[], Any] | Any = MISSING,
          compare: bool = True, repr: bool = True) -> Any:  # noqa: A002 - as dataclasses
    """A field with a default (or a factory making one per instance), left out of comparisons
    (``compare=False``) or of ``repr`` (``repr=False``)."""
    return Field(default, default_factory, compare, repr)


@overload
def record(cls: T, /) -> T:
    ...


@overload
def record(*, order: bool = False) -> Callable[[T], T]:
    ...


@dataclass_transform(frozen_default=True, field_specifiers=(field, Field))
def record(cls: Any = None, /, *, order: bool = False) -> Any:
    """Make ``cls`` an immutable, slotted record of its annotated fields (see the module's
    text); with ``order=True`` its instances also compare with ``<`` on those fields."""
    if cls is None:
        return lambda later: _make(later, order)
    return _make(cls, order)


def _make(cls: type, order: bool) -> type:
    namespace = dict(cls.__dict__)
    every: list[Field] = []
    for name, annotation in namespace.get("__annotations__", {}).items():
        if "ClassVar" in str(annotation):
            continue
        value = namespace.pop(name, MISSING)
        declared = value if isinstance(value, Field) else Field(default=value)
        declared.name = name
        every.append(declared)
    for inherited in ("__dict__", "__weakref__"):
        namespace.pop(inherited, None)
    names = tuple(f.name for f in every)
    shared = {**_SHARED, **(_ORDER if order else {})}
    namespace.update(__slots__=names, __match_args__=names, __record_fields__=tuple(every),
                     _names=names, _shown=tuple(f.name for f in every if f.repr),
                     _compared=staticmethod(_getter([f.name for f in every if f.compare])),
                     _values=staticmethod(_getter(list(names))),
                     **{name: function for name, function in shared.items()
                        if name not in namespace})
    made = type(cls)(cls.__name__, cls.__bases__, namespace)
    made.__qualname__ = cls.__qualname__
    made.__init__ = _first_initialiser(made, every)  # type: ignore[misc]
    return made


def _first_initialiser(cls: type, every: list[Field]) -> Callable[..., None]:
    """``cls.__init__`` until the first instance is made: it compiles the real one (below),
    puts it in its place and calls it. A run makes instances of about half of the seventy
    records its modules define, and compiling an ``__init__`` is most of defining one."""
    def __init__(self: Any, *args: Any, **kwargs: Any) -> None:
        initialiser = _initialiser(cls, every)
        cls.__init__ = initialiser  # type: ignore[misc]
        initialiser(self, *args, **kwargs)

    __init__.__qualname__ = f"{cls.__qualname__}.__init__"
    return __init__


def _initialiser(cls: type, every: list[Field]) -> Callable[..., None]:
    """``cls.__init__``: one argument per field (defaults and factories as declared), each
    value set past the frozen ``__setattr__``; then ``__post_init__`` when the class has one."""
    scope: dict[str, Any] = {"_set": object.__setattr__, "_MISSING": MISSING}
    arguments, body = ["self"], []
    for f in every:
        value = f.name
        if f.default is not MISSING:
            scope[f"_default_{f.name}"] = f.default
            arguments.append(f"{f.name}=_default_{f.name}")
        elif f.default_factory is not MISSING:
            scope[f"_factory_{f.name}"] = f.default_factory
            arguments.append(f"{f.name}=_MISSING")
            value = f"_factory_{f.name}() if {f.name} is _MISSING else {f.name}"
        else:
            arguments.append(f.name)
        body.append(f"    _set(self, {f.name!r}, {value})")
    if hasattr(cls, "__post_init__"):
        body.append("    self.__post_init__()")
    source = f"def __init__({', '.join(arguments)}):\n" + ("\n".join(body) or "    pass")
    exec(source, scope)  # noqa: S102 - our own text, built from field names
    function: Callable[..., None] = scope["__init__"]
    function.__qualname__ = f"{cls.__qualname__}.__init__"
    return function


def _getter(names: list[str]) -> Callable[[Any], tuple[Any, ...]]:
    """The values of the fields ``names`` of an instance, always as a tuple."""
    if not names:
        return lambda _: ()
    if len(names) == 1:
        single = attrgetter(names[0])
        return lambda instance: (single(instance),)
    return attrgetter(*names)


def fields(instance_or_class: Any) -> tuple[Field, ...]:
    """The fields of a record (class or instance), in order."""
    found: tuple[Field, ...] = instance_or_class.__record_fields__
    return found


def is_record(value: Any) -> bool:
    """True for a record class or instance."""
    return hasattr(value, "__record_fields__")


def replace(instance: R, /, **changes: Any) -> R:
    """A copy of the record ``instance`` with some fields changed."""
    names: tuple[str, ...] = instance._names  # type: ignore[attr-defined]
    values = {name: getattr(instance, name) for name in names}
    unknown = set(changes) - set(values)
    if unknown:
        raise TypeError(f"{type(instance).__qualname__} has no field {sorted(unknown)[0]!r}")
    values.update(changes)
    return type(instance)(**values)


def asdict(value: Any) -> Any:
    """A record as a dict of its fields, records in it (and in its lists, tuples and dicts)
    too, as ``dataclasses.asdict`` gives it."""
    if is_record(value) and not isinstance(value, type):
        return {name: asdict(getattr(value, name)) for name in value._names}
    if isinstance(value, (list, tuple)):
        return type(value)(asdict(item) for item in value)
    if isinstance(value, dict):
        return {asdict(key): asdict(item) for key, item in value.items()}
    return value


def _eq(self: Any, other: Any) -> Any:
    if other.__class__ is self.__class__:
        return self._compared(self) == other._compared(other)
    return NotImplemented


def _ordering(compare: Callable[[tuple[Any, ...], tuple[Any, ...]], bool]
              ) -> Callable[[Any, Any], Any]:
    def method(self: Any, other: Any) -> Any:
        if other.__class__ is self.__class__:
            return compare(self._compared(self), other._compared(other))
        return NotImplemented
    return method


def _hash(self: Any) -> int:
    return hash(self._compared(self))


def _repr(self: Any) -> str:
    shown = ", ".join(f"{name}={getattr(self, name)!r}" for name in self._shown)
    return f"{self.__class__.__qualname__}({shown})"


def _setattr(self: Any, name: str, value: Any) -> None:
    raise FrozenInstanceError(f"cannot assign to field {name!r}")


def _delattr(self: Any, name: str) -> None:
    raise FrozenInstanceError(f"cannot delete field {name!r}")


def _getstate(self: Any) -> tuple[Any, ...]:
    return self._values(self)


def _setstate(self: Any, state: tuple[Any, ...]) -> None:
    for name, value in zip(self._names, state):
        object.__setattr__(self, name, value)


_SHARED = {"__eq__": _eq, "__hash__": _hash, "__repr__": _repr, "__setattr__": _setattr,
           "__delattr__": _delattr, "__getstate__": _getstate, "__setstate__": _setstate}
_ORDER = {"__lt__": _ordering(lambda a, b: a < b), "__le__": _ordering(lambda a, b: a <= b),
          "__gt__": _ordering(lambda a, b: a > b), "__ge__": _ordering(lambda a, b: a >= b)}
