"""PYC040's reading of format specifications, checked against Python's own ``format``."""

from __future__ import annotations

import itertools

import pytest

from pkgtool.rules.python.text_formatted_as_number import refused_by_text

_PARTS = (("", "<", ">", "^", "=", "x<", "*=", "0>", "=<", "=="), ("", "+", "-", " "),
          ("", "z"), ("", "#"), ("", "0"), ("", "8", "12"), ("", ",", "_"), ("", ".3"),
          ("", "s", "d", "f", "e", "g", "%", "x", "c", "n", "b", "o", "X", "E", "F", "G"))
SPECS = sorted({"".join(parts) for parts in itertools.product(*_PARTS)})


def _error(spec: str) -> str | None:
    try:
        format("ab", spec)
    except (ValueError, TypeError) as error:
        return f"{type(error).__name__}: {error}"
    return None


def test_every_specification_is_read_as_python_reads_it() -> None:
    wrong = [(spec, refused_by_text(spec), _error(spec)) for spec in SPECS
             if (refused_by_text(spec) is None) != (_error(spec) is None)]
    assert not wrong[:20]


@pytest.mark.parametrize("spec", [".4f", "d", "+", "#", "=8", ",", "_", "z", "5.1%", "x"])
def test_the_message_is_pythons(spec: str) -> None:
    assert refused_by_text(spec) == _error(spec)


def test_number_refusals_are_what_format_raises() -> None:
    """PYC051 asks format() itself; a huge width is never tried."""
    from pkgtool.rules.python.number_format_refused import refused_by_number

    assert refused_by_number("d", "float") == \
        "ValueError: Unknown format code 'd' for object of type 'float'"
    assert refused_by_number(".2", "int") is not None
    assert refused_by_number(".2f", "int") is None
    assert refused_by_number("99999999999", "int") is None
    assert refused_by_number("s", "bool") is not None
