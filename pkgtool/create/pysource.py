"""Small writers of Python and YAML source that pass ament's flake8 settings.

Imports come out in flake8-import-order's google order (standard library first, then the rest,
each sorted case-insensitively by module); string literals use single quotes and are split
into implicitly concatenated pieces when a line would pass 99 characters.
"""

from __future__ import annotations

import json
import os
import time
import sys
from collections.abc import Iterable
from pkgtool.lazy_regex import lazy_pattern

MAX_LINE = 99
_PLAIN_YAML = lazy_pattern(r"^[A-Za-z_/][A-Za-z0-9_/.]*$")
_YAML_WORDS = {"true", "false", "yes", "no", "on", "off", "null", "y", "n", "~"}


def _key(module: str) -> tuple[str, str]:
    return (module.lower(), module)


def _line(module: str, names: tuple[str, ...]) -> str:
    if not names:
        return f"import {module}"
    line = f"from {module} import {', '.join(names)}"
    if len(line) <= MAX_LINE:
        return line
    return f"from {module} import (\n" + "".join(f"    {n},\n" for n in names) + ")"


def import_block(imports: Iterable[tuple[str, str | None]]) -> str:
    """Import lines for ``(module, name or None)`` pairs, grouped and sorted the google way.

    ``(module, None)`` is ``import module``; names from one module share one ``from`` line.
    """
    names: dict[str, set[str]] = {}
    plain: set[str] = set()
    for module, name in imports:
        names.setdefault(module, set())
        if name is None:
            plain.add(module)
        else:
            names[module].add(name)
    groups: list[list[str]] = [[], []]
    for module in sorted(names, key=_key):
        group = groups[0 if module.split(".")[0] in sys.stdlib_module_names else 1]
        if module in plain:
            group.append(_line(module, ()))
        if names[module]:
            group.append(_line(module, tuple(sorted(names[module], key=_key))))
    return "\n\n".join("\n".join(group) for group in groups if group)


def py_str(value: str, column: int, indent: int) -> str:
    """``value`` as a Python literal starting at ``column`` on a line indented ``indent``.

    ``repr`` quotes singly unless the text holds a single quote, as flake8-quotes wants. When
    the literal (plus a trailing comma) would pass 99 characters it becomes a parenthesised
    implicit concatenation of pieces, one per line.
    """
    literal = repr(value)
    if column + len(literal) + 1 <= MAX_LINE:
        return literal
    inner = " " * (indent + 4)
    width = MAX_LINE - len(inner) - 4
    pieces = [repr(value[i:i + width]) for i in range(0, len(value), width)]
    return "(\n" + "".join(f"{inner}{piece}\n" for piece in pieces) + " " * indent + ")"


def py_value(value: object) -> str:
    """A parameter default as Python source (single-quoted strings)."""
    return repr(value) if isinstance(value, str) else repr(value)


def yaml_value(value: object) -> str:
    """A parameter default as a YAML scalar."""
    if isinstance(value, str):
        plain = _PLAIN_YAML.match(value) and value.lower() not in _YAML_WORDS
        return value if plain else json.dumps(value)
    return json.dumps(value)


def copyright_year() -> int:
    """The year of SOURCE_DATE_EPOCH when set (reproducible output), else the current year."""
    epoch = os.environ.get("SOURCE_DATE_EPOCH", "")
    return time.gmtime(int(epoch) if epoch.isdigit() else None).tm_year
