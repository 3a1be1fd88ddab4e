"""The keywords common standard library calls take (``data/stdlib_signatures.txt``, Python
3.10-3.13), by the dotted name code calls them by (``builtins.print``, ``json.dump``)."""

from __future__ import annotations

from functools import cache

from pkgtool.knowledge.tables import read


@cache
def _table() -> dict[str, frozenset[str]]:
    table = read("stdlib_signatures")
    return {name: frozenset(table.values.get(name, "").split()) for name in table.flags}


def keywords_of(call: str) -> frozenset[str] | None:
    """The keywords ``call`` takes on some Python 3.10-3.13, None when the table does not hold
    it (it is not listed, or takes any keyword)."""
    return _table().get(call)
