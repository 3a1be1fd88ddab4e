"""What common standard library modules define (``data/stdlib_names.txt``, Python 3.10-3.13)."""

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
