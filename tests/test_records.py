"""``@record`` behaves as ``@dataclass(frozen=True, slots=True)`` where pkgtool relies on it."""

from __future__ import annotations

import copy
import pickle
from dataclasses import dataclass
from dataclasses import field as dataclass_field
from typing import ClassVar, Generic, TypeVar

import pytest

from pkgtool.records import FrozenInstanceError, asdict, field, fields, is_record, record, replace

T = TypeVar("T")


@record
class Point:
    """A record with a plain field, a factory, a field left out of comparisons and one of repr."""

    x: int
    tags: list[str] = field(default_factory=list)
    note: str = field(default="", compare=False)
    secret: str = field(default="s", repr=False)
    LIMIT: ClassVar[int] = 3


@dataclass(frozen=True)
class Twin:
    """The same fields as a standard dataclass, for comparison."""

    x: int
    tags: list[str] = dataclass_field(default_factory=list)
    note: str = dataclass_field(default="", compare=False)
    secret: str = dataclass_field(default="s", repr=False)


@record(order=True)
class Pair(Generic[T]):
    """An ordered, generic record."""

    first: T
    second: int = 0


def test_construction_equality_hash_and_repr_match_a_frozen_dataclass() -> None:
    assert Point(1) == Point(1, [], "other note") and Point(1) != Point(2)
    assert Point(1).tags is not Point(1).tags
    assert repr(Point(1, ["a"])) == repr(Twin(1, ["a"])).replace("Twin", "Point")
    assert hash(Point(3, (), "n")) == hash(Point(3, ()))  # type: ignore[arg-type]
    assert Point(1) != Twin(1) and (Point(1) == (1,)) is False
    assert Point.LIMIT == 3 and [f.name for f in fields(Point)] == ["x", "tags", "note", "secret"]
    with pytest.raises(TypeError):
        Point()  # type: ignore[call-arg]


def test_order_compares_fields_in_turn_and_only_within_the_class() -> None:
    pairs = [Pair("b"), Pair("a", 2), Pair("a", 1)]
    assert sorted(pairs) == [Pair("a", 1), Pair("a", 2), Pair("b")]
    assert Pair("a") <= Pair("a") and Pair("b") > Pair("a") >= Pair("a")
    with pytest.raises(TypeError):
        assert Pair("a") < ("a", 0)  # type: ignore[operator]


def test_fields_cannot_change_and_there_is_no_instance_dict() -> None:
    point = Point(1)
    with pytest.raises(FrozenInstanceError):
        point.x = 2  # type: ignore[misc]
    with pytest.raises(AttributeError):
        del point.x
    assert not hasattr(point, "__dict__") and Point.__slots__ == ("x", "tags", "note", "secret")


def test_it_pickles_copies_replaces_and_converts_to_a_dict() -> None:
    point = Point(1, ["a"], "n")
    assert pickle.loads(pickle.dumps(point)) == point
    assert copy.deepcopy(point) == point and copy.copy(point) == point
    assert replace(point, x=5) == Point(5, ["a"]) and replace(point, x=5).note == "n"
    with pytest.raises(TypeError):
        replace(point, y=1)
    assert asdict(Pair(point, 2)) == {"first": {"x": 1, "tags": ["a"], "note": "n",
                                                "secret": "s"}, "second": 2}
    assert is_record(point) and is_record(Point) and not is_record(Twin(1))


def test_post_init_runs_after_the_fields_are_set() -> None:
    seen = []

    @record
    class Checked:
        """Calls ``__post_init__``."""

        value: int

        def __post_init__(self) -> None:
            seen.append(self.value)

    Checked(4)
    assert seen == [4]


def test_the_first_instance_may_come_from_a_subclass_and_a_wrong_call_fails_as_usual() -> None:
    @record
    class Base:
        """A record whose first instance is a plain subclass's."""

        a: int
        b: str = "b"

    class Child(Base):
        __slots__ = ()

    with pytest.raises(TypeError):
        Base()  # type: ignore[call-arg]
    assert Child(1).b == "b" and Child(1) != Base(1)
    assert Base(2, b="c") == Base(2, "c")
    assert Base.__init__.__qualname__.endswith("Base.__init__")
