"""Edits, fixes, conflicts and splicing."""

from __future__ import annotations

import pytest

from pkgtool.edit import Edit, EditError, Fix, apply_edits, conflicts, select_fixes


def test_splice_keeps_everything_outside_the_spans() -> None:
    text = "alpha\r\nbeta\r\ngamma\r\n"
    edits = [Edit("f", 0, 5, "ALPHA"), Edit("f", 7, 7, "new\r\n"), Edit("f", 13, 18, "")]
    assert apply_edits(text, edits) == "ALPHA\r\nnew\r\nbeta\r\n\r\n"


def test_identical_edits_apply_once() -> None:
    edit = Edit("f", 1, 1, "x")
    assert apply_edits("ab", [edit, edit]) == "axb"
    assert conflicts([edit, edit]) == []


@pytest.mark.parametrize(("first", "second"), [
    ((0, 4), (2, 6)),   # overlapping replacements
    ((3, 3), (3, 3)),   # two different insertions at one point: order unknown
    ((0, 6), (3, 3)),   # an insertion inside a replaced span
])
def test_overlapping_edits_conflict(first: tuple[int, int], second: tuple[int, int]) -> None:
    a, b = Edit("f", *first, "A"), Edit("f", *second, "B")
    assert conflicts([a, b]) == [tuple(sorted((a, b)))]
    with pytest.raises(EditError, match="overlap"):
        apply_edits("abcdefgh", [a, b])


def test_touching_edits_and_other_files_do_not_conflict() -> None:
    edits = [Edit("f", 0, 3, "x"), Edit("f", 3, 3, "y"), Edit("f", 3, 5, "z"), Edit("g", 0, 9, "")]
    assert conflicts(edits) == []
    assert apply_edits("abcdefg", edits[:3]) == "xyzfg"


def test_a_new_file_conflicts_with_any_other_edit_of_it() -> None:
    created = Edit("new.py", 0, 0, "text", create=True)
    assert conflicts([created, Edit("new.py", 0, 0, "other", create=True)])


def test_select_fixes_defers_a_fix_that_conflicts_with_an_earlier_one() -> None:
    first = Fix("first", (Edit("f", 0, 2, "x"), Edit("g", 0, 0, "y")))
    clash = Fix("clash", (Edit("f", 1, 3, "z"),))
    free = Fix("free", (Edit("f", 5, 6, ""),), safe=False)
    chosen, deferred = select_fixes([first, clash, free])
    assert chosen == [first, free] and deferred == [clash]
    assert first.paths == ("f", "g")


def test_bad_spans_are_rejected() -> None:
    with pytest.raises(ValueError):
        Edit("f", 3, 2, "")
    with pytest.raises(EditError, match="past its end"):
        apply_edits("ab", [Edit("f", 1, 5, "")])
