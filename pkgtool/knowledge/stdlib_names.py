"""What common standard library modules (``data/stdlib_names.txt``, Python 3.10-3.13) and NumPy
(``data/numpy_names.txt``) define."""

from __future__ import annotations

from functools import cache

from pkgtool.knowledge.tables import read


@cache
def stdlib_names() -> dict[str, tuple[frozenset[str], bool]]:
    """For each module of the table (``os.path`` too), the names it defines on some Python
    3.10-3.13 and whether that list holds on every platform (False: Linux's names, a spelling
    reference only)."""
    table = read("stdlib_names")
    return {module: (frozenset(table.values.get(module, "").split()), flags == "portable")
            for module, flags in table.flags.items()}


@cache
def numpy_names() -> dict[str, tuple[frozenset[str], bool]]:
    """For each module of ``data/numpy_names.txt`` (``numpy``, ``numpy.linalg``, ...), the names
    it defines in some NumPy from 1.23 to 2.x; never complete (a newer release may add names):
    a spelling reference."""
    table = read("numpy_names")
    return {module: (frozenset(table.values.get(module, "").split()), False)
            for module in table.flags}
