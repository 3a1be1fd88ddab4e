"""SET005: setup.py's license is none of package.xml's licenses."""

from __future__ import annotations

import re
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.licenses import spdx_ids_for
from pkgtool.model.package import Package
from pkgtool.rules.registry import rule
from pkgtool.rules.setup_values import checked_setup, same_text, text_of

_SEPARATORS = re.compile(r"\s+(?:or|and)\s+|\s*[,;/]\s*", re.IGNORECASE)


def _loose(text: str) -> str:
    """``Apache License, Version 2.0`` -> ``apache2``; ``GPLv3 only`` -> ``gpl3``."""
    words = re.sub(r"\b(?:licen[sc]e|version|the|only)\b", " ", text.lower())
    compact = re.sub(r"v(?=\d)", "", re.sub(r"[^a-z0-9.]", "", words))
    return re.sub(r"\.0(?=\D|$)", "", compact)


def _matches(license_text: str, declared: list[str]) -> bool:
    ids = set(spdx_ids_for(license_text))
    return any(same_text(license_text, d) or ids & set(spdx_ids_for(d)) or
               _loose(license_text) == _loose(d) for d in declared)


@rule("SET005", "setup-license-mismatch", Severity.WARNING,
      fix="Use the `<license>` of `package.xml` in `setup(license=...)`")
def setup_license_mismatch(package: Package) -> Iterator[Hit]:
    """`setup(license=...)` names a license package.xml does not declare.

    ## What it does
    Compares the statically known `license` keyword with package.xml's `<license>` tags,
    ignoring case and common spellings of the same license (`Apache License 2.0` and
    `Apache-2.0` agree). With several licenses, any one of them, or a list of them
    (`Apache-2.0 OR MIT`, `Apache-2.0, MIT`), matches.

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
    parts = [p for p in _SEPARATORS.split(text.strip()) if p]
    if _matches(text, declared) or (parts and all(_matches(p, declared) for p in parts)):
        return
    shown = ", ".join(f"`{d}`" for d in declared)
    yield Hit(span, f"`setup.py` license `{text}` is not the `package.xml` license {shown}")
