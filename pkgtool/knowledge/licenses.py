"""Licenses ROS 2 packages use: SPDX identifiers, their common aliases, and header phrases."""

from __future__ import annotations

import re

SPDX_ALIASES: dict[str, tuple[str, ...]] = {
    "Apache-2.0": ("apache-2.0", "apache 2.0", "apache license 2.0", "apache2", "apache 2",
                   "apache license, version 2.0", "apache license version 2.0", "alv2"),
    "BSL-1.0": ("bsl-1.0", "boost software license 1.0", "boost software license, version 1.0",
                "boost"),
    "BSD-2-Clause": ("bsd-2-clause", "bsd 2-clause", "2-clause bsd", "simplified bsd",
                     "bsd-2"),
    "BSD-3-Clause": ("bsd-3-clause", "bsd 3-clause", "3-clause bsd", "new bsd", "bsd-3",
                     "modified bsd"),
    "MIT": ("mit", "mit license", "expat"),
    "MIT-0": ("mit-0", "mit no attribution"),
    "GPL-3.0-only": ("gpl-3.0-only", "gpl-3.0", "gplv3", "gpl v3", "gpl3", "gpl-3",
                     "gnu general public license 3.0", "gnu gpl v3"),
    "LGPL-3.0-only": ("lgpl-3.0-only", "lgpl-3.0", "lgplv3", "lgpl v3", "lgpl3", "lgpl-3",
                      "gnu lesser general public license 3.0"),
}
"""SPDX id -> lower-case spellings seen in package.xml files for it."""

AMBIGUOUS = {"bsd": ("BSD-2-Clause", "BSD-3-Clause"), "gpl": ("GPL-3.0-only",),
             "lgpl": ("LGPL-3.0-only",)}

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

_SPDX_LINE = re.compile(r"SPDX-License-Identifier:\s*([A-Za-z0-9.+\-() ]+?)\s*(?:\*/|-->)?\s*$",
                        re.MULTILINE)


def spdx_ids_for(license_text: str) -> tuple[str, ...]:
    """SPDX ids a package.xml ``<license>`` value stands for (empty when unknown)."""
    key = " ".join(license_text.lower().split())
    for spdx, aliases in SPDX_ALIASES.items():
        if key == spdx.lower() or key in aliases:
            return (spdx,)
    return AMBIGUOUS.get(key, ())


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
