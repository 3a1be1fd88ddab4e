"""What the evaluator may spend: sizes are checked before a string, list or int is built.

setup.py is untrusted input (``pkgtool lint`` in pre-commit, the grader as root): one line
like ``'{:>1500000000}'.format('x')``, a loop squaring an int or a nested ``**`` glob must
not cost the reader gigabytes or minutes. Every operation that builds a value first
estimates its size (:data:`MAX_SIZE` characters or items, :data:`MAX_INT_BITS` bits) and
charges its work to a per-file :class:`Budget`; past a bound the evaluation of that
statement is refused (``OutOfBudget``), which lint reports as not evaluated.
"""

from __future__ import annotations

import string
from typing import Any
from pkgtool.lazy_regex import lazy_pattern

MAX_STEPS = 200_000
"""Evaluation steps before the evaluator gives up (loops over huge globs, runaway code)."""
MAX_SIZE = 100_000
"""Longest string or list the evaluator builds."""
MAX_INT_BITS = 65_536
"""Largest int the evaluator builds, in bits."""
MAX_COST = 20_000_000
"""Work units (characters or items touched) one setup.py may cost in all."""

_SPEC = lazy_pattern(r"(?:.?[<>=^])?[-+ ]?z?#?0?(?P<width>\d*)[,_]?(?:\.(?P<precision>\d+))?"
                     r"[bcdeEfFgGnosxX%]?")
_PERCENT = lazy_pattern(r"%(?:\([^)]*\))?[#0\- +]*(?P<width>\*|\d*)(?:\.(?P<precision>\*|\d*))?"
                        r"[hlL]?[diouxXeEfFgGcrsa%]")


class TooLarge(Exception):
    """An operation would build a value past the bounds or cost past the budget."""


class Budget:
    """The work one evaluation has left."""

    def __init__(self) -> None:
        self.cost = 0

    def charge(self, units: int) -> None:
        """Spend ``units``; TooLarge once the total passes MAX_COST."""
        self.cost += max(1, units)
        if self.cost > MAX_COST:
            raise TooLarge("budget")

    def size(self, units: int) -> int:
        """Charge a value of ``units`` characters/items about to be built; TooLarge if huge."""
        if units > MAX_SIZE:
            raise TooLarge("size")
        self.charge(units)
        return units


def length(value: Any) -> int:
    """``len(value)`` for sized values, else 1."""
    return len(value) if hasattr(value, "__len__") else 1


def scalar_size(value: Any) -> int:
    """An upper bound of ``str(value)``'s length for plain data, without building it."""
    if isinstance(value, int) and not isinstance(value, bool):
        return value.bit_length() // 3 + 2
    if isinstance(value, (str, list, tuple, dict, set, frozenset)):
        return len(value) if isinstance(value, str) else \
            sum(scalar_size(v) + 4 for v in value) + 2
    return 32


def binary_size(op: str, left: Any, right: Any) -> int:
    """The size of ``left op right`` (items, characters, or int words) before computing it."""
    sequences = (str, list, tuple)
    if op == "Mult":
        for seq, times in ((left, right), (right, left)):
            if isinstance(seq, sequences) and isinstance(times, int):
                return len(seq) * max(0, times)
    if op == "Add" and isinstance(left, sequences) and isinstance(right, sequences):
        return len(left) + len(right)
    if isinstance(left, int) and isinstance(right, int):
        bits = left.bit_length() + right.bit_length() if op == "Mult" else \
            max(left.bit_length(), right.bit_length()) + 1
        if bits > MAX_INT_BITS:
            raise TooLarge("int")
        return bits // 64
    return 1


def spec_size(value: Any, spec: str) -> int:
    """The most characters ``format(value, spec)`` produces; TooLarge for huge specs."""
    match = _SPEC.fullmatch(spec)
    if match is None:
        raise TooLarge("format spec")
    width = int(match["width"] or 0)
    precision = int(match["precision"] or 0)
    if width > MAX_SIZE or precision > MAX_SIZE:
        raise TooLarge("format width")
    return max(width, precision + 2 * scalar_size(value) + 16)


class _Formatter(string.Formatter):
    """``str.format`` that checks every field's size before formatting it."""

    def __init__(self, budget: Budget) -> None:
        self.budget, self.total = budget, 0

    def format_field(self, value: Any, format_spec: str) -> Any:
        self.total += spec_size(value, format_spec)
        self.budget.size(self.total)
        return super().format_field(value, format_spec)


def bounded_format(budget: Budget, template: str, args: list[Any],
                   kwargs: dict[str, Any]) -> str:
    """``template.format(*args, **kwargs)`` within the bounds."""
    budget.size(len(template))
    return _Formatter(budget).vformat(template, args, kwargs)


def bounded_percent(budget: Budget, template: str, values: Any) -> str:
    """``template % values`` within the bounds (``*`` widths are refused)."""
    total = len(template) + scalar_size(values)
    for match in _PERCENT.finditer(template):
        if "*" in (match["width"], match["precision"]):
            raise TooLarge("* width")
        total += int(match["width"] or 0) + int(match["precision"] or 0)
    budget.size(total)
    return template % values


def bounded_replace(budget: Budget, text: str, args: list[Any]) -> str:
    """``text.replace(*args)`` within the bounds."""
    if len(args) not in (2, 3) or not all(isinstance(a, str) for a in args[:2]):
        raise TypeError("replace")
    old, new = args[0], args[1]
    count = text.count(old) if old else len(text) + 1
    if len(args) == 3 and isinstance(args[2], int) and args[2] >= 0:
        count = min(count, args[2])
    budget.size(len(text) + count * max(0, len(new) - len(old)))
    return text.replace(*args)


def bounded_join(budget: Budget, separator: str, sizes: list[int]) -> None:
    """Check that ``separator.join`` of items of these ``sizes`` stays within the bounds."""
    budget.size(sum(sizes) + len(separator) * max(0, len(sizes) - 1))
