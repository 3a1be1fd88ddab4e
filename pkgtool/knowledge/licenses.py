"""Licenses ROS 2 packages use: SPDX identifiers, their common aliases, and header phrases."""

from __future__ import annotations

import re
from pkgtool.lazy_regex import lazy_pattern

SPDX_ALIASES: dict[str, tuple[str, ...]] = {
    "Apache-2.0": ("apache 2.0", "apache license 2.0", "apache2", "apache 2", "apache2.0",
                   "apache-2", "apache v2", "apache v2.0", "apache 2.0 license",
                   "apache license v2.0", "apache license, version 2.0",
                   "apache license version 2.0", "alv2", "al2", "asl 2.0", "asl2.0"),
    "BSL-1.0": ("boost software license 1.0", "boost software license, version 1.0",
                "boost software license", "boost 1.0", "boost"),
    "BSD-2-Clause": ("bsd 2-clause", "2-clause bsd", "simplified bsd", "bsd-2", "bsd2",
                     "bsd 2 clause", "freebsd"),
    "BSD-3-Clause": ("bsd 3-clause", "3-clause bsd", "new bsd", "bsd new", "bsd-3", "bsd3",
                     "bsd 3 clause", "modified bsd", "bsd 3-clause license",
                     "bsd-3-clause license"),
    "MIT": ("mit license", "the mit license", "expat"),
    "MIT-0": ("mit no attribution",),
    "GPL-2.0-only": ("gplv2", "gpl v2", "gpl-2", "gpl2", "gpl 2", "gnu gpl v2",
                     "gpl version 2", "gnu general public license 2.0"),
    "GPL-3.0-only": ("gplv3", "gpl v3", "gpl3", "gpl-3", "gpl 3", "gnu gpl v3", "gpl version 3",
                     "gnu general public license 3.0"),
    "LGPL-2.1-only": ("lgplv2.1", "lgpl v2.1", "lgpl-2.1", "lgpl2.1"),
    "LGPL-3.0-only": ("lgplv3", "lgpl v3", "lgpl3", "lgpl-3",
                      "gnu lesser general public license 3.0"),
    "MPL-2.0": ("mpl 2.0", "mpl2", "mpl-2", "mpl2.0", "mozilla public license 2.0"),
    "EPL-2.0": ("epl 2.0", "epl2", "epl-2", "eclipse public license 2.0"),
}
"""SPDX id -> lower-case informal spellings seen in package.xml and setup.py for it.

SPDX identifiers and expressions themselves (any case, deprecated ids included) need no entry:
:func:`spdx_expression` reads them with ``packaging.licenses``, whose SPDX list follows the
upstream license list.
"""

AMBIGUOUS = {"bsd": ("BSD-2-Clause", "BSD-3-Clause"), "gpl": ("GPL-3.0-only",),
             "lgpl": ("LGPL-3.0-only",)}

_BY_ALIAS = {alias: spdx for spdx, aliases in SPDX_ALIASES.items()
             for alias in (spdx.lower(), *aliases)}
"""Informal spellings and (a fast path that spares importing packaging's SPDX list) the ids."""
_OPERATORS = frozenset({"AND", "OR", "WITH", "(", ")"})
_GNU = lazy_pattern(r"^(A?GPL|LGPL|GFDL)-(\d\.\d)(-only|-or-later|\+)?$")


def spdx_expression(text: str) -> str | None:
    """``text`` as a canonical SPDX license expression, or None when it is not one."""
    from packaging.licenses import InvalidLicenseExpression, canonicalize_license_expression

    try:
        return canonicalize_license_expression(text)
    except InvalidLicenseExpression:
        return None


def _ids_of(expression: str) -> tuple[str, ...]:
    """License ids of a canonical expression (exceptions dropped), GNU ids made explicit."""
    tokens = expression.replace("(", " ( ").replace(")", " ) ").split()
    ids: list[str] = []
    skip = False
    for token in tokens:
        if token in _OPERATORS:
            skip = token == "WITH"
            continue
        if not skip:
            gnu = _GNU.match(token)
            ids.append(f"{gnu.group(1)}-{gnu.group(2)}-"
                       f"{'or-later' if gnu.group(3) in ('+', '-or-later') else 'only'}"
                       if gnu else token)
        skip = False
    return tuple(dict.fromkeys(ids))


def spdx_ids_for(license_text: str) -> tuple[str, ...]:
    """SPDX ids a license value stands for (empty when unknown).

    Informal spellings first (``Apache License 2.0``), then any SPDX identifier or expression
    (``apache-2.0``, ``Apache-2.0 OR MIT``, deprecated ``GPL-3.0``). ``BSD`` alone stands for
    both BSD variants.
    """
    key = " ".join(license_text.lower().split())
    if key in _BY_ALIAS:
        return (_BY_ALIAS[key],)
    if key in AMBIGUOUS:
        return AMBIGUOUS[key]
    expression = spdx_expression(license_text) if license_text.strip() else None
    return _ids_of(expression) if expression else ()


def gnu_choices(spdx_id: str) -> tuple[str, ...]:
    """What a deprecated GNU id means today: ``GPL-3.0`` is ``GPL-3.0-only`` or
    ``GPL-3.0-or-later``, ``GPL-3.0+`` is ``GPL-3.0-or-later``; empty for any other id."""
    gnu = _GNU.match(spdx_id)
    if gnu is None or gnu.group(3) in ("-only", "-or-later"):
        return ()
    base = f"{gnu.group(1)}-{gnu.group(2)}"
    return (f"{base}-or-later",) if gnu.group(3) == "+" else (f"{base}-only", f"{base}-or-later")


def same_license(left: str, right: str) -> bool:
    """True when two SPDX ids name one license (GNU ``-only``/``-or-later`` of one version too)."""
    if left == right:
        return True
    first, second = _GNU.match(left), _GNU.match(right)
    return bool(first and second and first.group(1, 2) == second.group(1, 2))


# Phrases that identify a license header (whitespace-normalised, case-insensitive); the
# first matching entry wins, so more specific licenses come first.
_HEADER_PHRASES: tuple[tuple[str, tuple[str, ...], tuple[str, ...]], ...] = (
    ("Apache-2.0", ("licensed under the apache license, version 2.0",), ()),
    ("BSL-1.0", ("boost software license",), ()),
    ("LGPL-3.0-only", ("gnu lesser general public license", "version 3"), ()),
    ("GPL-3.0-only", ("gnu general public license", "version 3"), ("lesser",)),
    ("BSD-3-Clause", ("redistribution and use in source and binary forms",
                      "neither the name of"), ()),
    ("BSD-2-Clause", ("redistribution and use in source and binary forms",),
     ("neither the name of",)),
    ("MIT", ("permission is hereby granted, free of charge",
             "the above copyright notice and this permission notice shall be included"), ()),
    ("MIT-0", ("permission is hereby granted, free of charge",), ("the above copyright notice",)),
)

_SPDX_LINE = lazy_pattern(r"SPDX-License-Identifier:\s*([A-Za-z0-9.+\-() ]+?)\s*(?:\*/|-->)?\s*$",
                          re.MULTILINE)


def spdx_in_text(text: str) -> str | None:
    """The expression of an ``SPDX-License-Identifier:`` line, if any."""
    match = _SPDX_LINE.search(text)
    return match.group(1).strip() if match else None


def license_of_header(text: str) -> str | None:
    """The SPDX id whose standard header text appears in ``text`` (comment markers removed)."""
    flat = " ".join(text.lower().split())
    for spdx, required, forbidden in _HEADER_PHRASES:
        if all(p in flat for p in required) and not any(p in flat for p in forbidden):
            return spdx
    return None
