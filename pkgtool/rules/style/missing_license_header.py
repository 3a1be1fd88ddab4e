"""CPY002: a source file whose header names no recognisable license."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule
from pkgtool.rules.style._headers import headers


@rule("CPY002", "missing-license-header", Severity.ERROR, default_enabled=False,
      fix="Add `# SPDX-License-Identifier: <id>` or the license's standard header")
def missing_license_header(package: Package) -> Iterator[Hit]:
    """A file has a copyright notice but no license header pkgtool recognises.

    ## What it does
    Accepts an `SPDX-License-Identifier:` comment line, or the standard header text of the
    licenses `ros2 pkg create` offers (Apache-2.0, BSL-1.0, BSD-2-Clause, BSD-3-Clause, MIT,
    MIT-0, GPL-3.0-only, LGPL-3.0-only). Files without a copyright notice are CPY001's.
    Enabled by `--style`.

    ## Why is this bad?
    ament_copyright reports `license=<unknown>` for such files and fails the test; readers
    cannot tell under which terms the file may be used.

    ## Example
    ```python
    # Copyright 2026 Ada Lovelace
    # All rights reserved, maybe.
    ```

    ## Use instead
    ```python
    # Copyright 2026 Ada Lovelace
    # SPDX-License-Identifier: Apache-2.0
    ```
    """
    for path, header in headers(package):
        if header.copyright_line is not None and header.license is None:
            yield Hit(Span(path, header.copyright_line, 1),
                      f"`{path}` has a copyright notice but no recognisable license")
