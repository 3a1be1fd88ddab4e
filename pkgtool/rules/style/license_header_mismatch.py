"""CPY003: a file header's license disagrees with package.xml."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.licenses import same_license, spdx_ids_for
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule
from pkgtool.rules.style._headers import headers


def _declared(package: Package) -> set[str] | None:
    """SPDX ids package.xml declares; None when a license is not one pkgtool can map."""
    if package.manifest is None or not package.manifest.licenses:
        return None
    ids: set[str] = set()
    for text in package.manifest.licenses:
        mapped = spdx_ids_for(text.value)
        if not mapped:
            return None
        ids.update(mapped)
    return ids


@rule("CPY003", "license-header-mismatch", Severity.ERROR, default_enabled=False,
      fix="Make the header's license one of the licenses package.xml declares")
def license_header_mismatch(package: Package) -> Iterator[Hit]:
    """A file's license header names a license that package.xml does not declare.

    ## What it does
    Compares the license of each file header (SPDX line or standard header text) with the
    `<license>` elements of package.xml, understanding every SPDX identifier and expression
    (`packaging.licenses`; `GPL-3.0-only` and `GPL-3.0-or-later` count as one license) and
    common spellings ("Apache License 2.0", "BSD", "GPLv3"). A header expression agrees when
    one of its licenses is declared. Unknown package.xml licenses are not judged. Enabled by
    `--style`.

    ## Why is this bad?
    Packagers (bloom, Debian) and users trust package.xml; a file under other terms is a
    licensing error that is expensive to discover late.

    ## Example
    ```python
    # Copyright 2026 Ada Lovelace
    # SPDX-License-Identifier: MIT
    ```
    with `<license>Apache-2.0</license>` in package.xml.

    ## Use instead
    ```python
    # Copyright 2026 Ada Lovelace
    # SPDX-License-Identifier: Apache-2.0
    ```
    """
    declared = _declared(package)
    if not declared:
        return
    for path, header in headers(package):
        if header.license is None or header.license_line is None:
            continue
        found = spdx_ids_for(header.license) or (header.license,)
        if not any(same_license(i, d) for i in found for d in declared):
            yield Hit(Span(path, header.license_line, 1),
                      f"`{path}` is licensed `{header.license}` but package.xml declares "
                      f"`{', '.join(sorted(declared))}`")
