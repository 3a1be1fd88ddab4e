"""SET005: setup.py's license is none of package.xml's licenses."""

from __future__ import annotations

import re
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.licenses import AMBIGUOUS, same_license, spdx_expression, spdx_ids_for
from pkgtool.model.package import Package
from pkgtool.rules.registry import rule
from pkgtool.rules.setup_values import checked_setup, same_text, text_of
from pkgtool.lazy_regex import lazy_pattern

_SEPARATORS = lazy_pattern(r"\s+(?:or|and)\s+|\s*[,;/]\s*", re.IGNORECASE)
_FAMILIES = frozenset({"bsd", "gpl", "lgpl", "agpl", "apache", "mpl", "epl", "mit"})


def _loose(text: str) -> str:
    """``Apache License, Version 2.0`` -> ``apache2``; ``GPLv3 only`` -> ``gpl3``."""
    words = re.sub(r"\b(?:licen[sc]e|version|the|only)\b", " ", text.lower())
    compact = re.sub(r"v(?=\d)", "", re.sub(r"[^a-z0-9.]", "", words))
    return re.sub(r"\.0(?=\D|$)", "", compact)


def _same_name(left: str, right: str) -> bool:
    """Equal loosely, or a bare family name (``BSD``) against a member (``BSD License 2.0``)."""
    first, second = _loose(left), _loose(right)
    return bool(first) and (first == second or (first in _FAMILIES and second.startswith(first))
                            or (second in _FAMILIES and first.startswith(second)))


def _matches(license_text: str, declared: list[str]) -> bool:
    """One license (or one of alternatives, like ``BSD``) is one of ``declared``."""
    ids = spdx_ids_for(license_text)
    if len(ids) > 1 and " ".join(license_text.lower().split()) not in AMBIGUOUS:
        ids = ()  # an expression of several licenses: _agrees checks each
    return any(same_text(license_text, d) or _same_name(license_text, d)
               or any(same_license(i, j) for i in ids for j in spdx_ids_for(d))
               for d in declared)


def _parts(text: str, declared: list[str]) -> list[str]:
    """``text`` split at separators, rejoining pieces that only together name a license
    (``Apache License, Version 2.0, BSD`` -> the Apache license and ``BSD``)."""
    pieces = [p for p in _SEPARATORS.split(text.strip()) if p]
    parts, start = [], 0
    while start < len(pieces):
        end = next((end for end in range(len(pieces), start, -1)
                    if _matches(", ".join(pieces[start:end]), declared)), start + 1)
        parts.append(", ".join(pieces[start:end]))
        start = end
    return parts


def _agrees(text: str, declared: list[str]) -> bool:
    if _matches(text, declared):
        return True
    expression = spdx_expression(text)
    if expression is not None and " " in expression:  # every license of the expression
        return all(_matches(i, declared) for i in spdx_ids_for(expression))
    parts = _parts(text, declared)
    return bool(parts) and all(_matches(p, declared) for p in parts)


@rule("SET005", "setup-license-mismatch", Severity.WARNING,
      fix="Use the `<license>` of `package.xml` in `setup(license=...)`")
def setup_license_mismatch(package: Package) -> Iterator[Hit]:
    """`setup(license=...)` names a license package.xml does not declare.

    ## What it does
    Compares the statically known `license` keyword with package.xml's `<license>` tags,
    ignoring case and spellings of the same license: every SPDX identifier and expression
    (read with `packaging.licenses`, deprecated ids included), common names (`Apache License
    2.0` and `Apache-2.0` agree), and a family name against a member (`BSD` and `BSD License
    2.0`). With several licenses, any one of them, or a list of them (`Apache-2.0 OR MIT`,
    `Apache License, Version 2.0, BSD`), matches when each license it names is declared.

    ## Why is this bad?
    The license in the installed Python metadata contradicts the one the package is released
    under; license scanners and users get two different answers.

    ## Example
    ```python
    setup(license='MIT', ...)   # package.xml: <license>Apache-2.0</license>
    ```

    ## Use instead
    ```python
    setup(license='Apache-2.0', ...)
    ```
    """
    setup = checked_setup(package)
    manifest = package.manifest
    found = text_of(setup.license) if setup else None
    if found is None or manifest is None or not manifest.licenses:
        return
    text, span = found
    declared = [license.value for license in manifest.licenses]
    if _agrees(text, declared):
        return
    shown = ", ".join(f"`{d}`" for d in declared)
    yield Hit(span, f"`setup.py` license `{text}` is not the `package.xml` license {shown}")
