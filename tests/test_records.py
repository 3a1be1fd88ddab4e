"""``@record`` behaves as ``@dataclass(frozen=True, slots=True)`` where pkgtool relies on it."""

from __future__ import annotations

import copy
import dataclasses
import pickle
from dataclasses import dataclass, field

import pytest

from pkgtool.records import record


@record
class Point:
    """A record with a plain field, a factory, a field left out of comparisons and one of repr."""

    x: int
    tags: list[str] = field(default_factory=list)
    note: str = field(default="", compare=False)
    secret: str = field(default="s", repr=False)


@dataclass(frozen=True, slots=True)
class Twin:
    """The same fields as a standard dataclass, for comparison."""

    x: int
    tags: list[str] = field(default_factory=list)
    note: str = field(default="", compare=False)
    secret: str = field(default="s", repr=False)


def test_construction_equality_hash_and_repr_match_a_frozen_dataclass() -> None:
    assert Point(1) == Point(1, [], "other note") and Point(1) != Point(2)
    assert Point(1).tags is not Point(1).tags
    assert repr(Point(1, ["a"])) == repr(Twin(1, ["a"])).replace("Twin", "Point")
    hashable = Point(3, note="n")
    assert hash(dataclasses.replace(hashable, tags=())) == hash(Point(3, ()))
    assert Point(1) != Twin(1) and (Point(1) == (1,)) is False


def test_fields_cannot_change_and_there_is_no_instance_dict() -> None:
    point = Point(1)
    with pytest.raises(dataclasses.FrozenInstanceError):
        point.x = 2  # type: ignore[misc]
    with pytest.raises(dataclasses.FrozenInstanceError):
        del point.x
    assert not hasattr(point, "__dict__")


def test_it_is_a_dataclass_that_pickles_copies_and_replaces() -> None:
    point = Point(1, ["a"], "n")
    assert [f.name for f in dataclasses.fields(point)] == ["x", "tags", "note", "secret"]
    assert pickle.loads(pickle.dumps(point)) == point
    assert copy.deepcopy(point) == point and copy.copy(point) == point
    assert dataclasses.replace(point, x=5) == Point(5, ["a"])
    assert dataclasses.asdict(point)["tags"] == ["a"]


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
