"""MAN019: a common license name written instead of its SPDX identifier (opt-in, info)."""

from __future__ import annotations

import re
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.manifest.common import tree
from pkgtool.rules.registry import rule

_ALIASES: dict[tuple[str, ...], tuple[str, ...]] = {
    ("apache 2", "apache 2.0", "apache2", "apache2.0", "apache-2", "apache v2", "apache v2.0",
     "apache license 2.0", "apache license, version 2.0", "apache license version 2.0",
     "apache 2.0 license", "apache license v2.0", "al2", "asl 2.0", "asl2.0"): ("Apache-2.0",),
    ("mit license", "the mit license", "expat"): ("MIT",),
    ("bsd 3-clause", "bsd-3", "bsd3", "bsd 3 clause", "3-clause bsd", "new bsd", "bsd new",
     "bsd 3-clause license", "bsd-3-clause license", "modified bsd"): ("BSD-3-Clause",),
    ("bsd 2-clause", "bsd-2", "bsd2", "bsd 2 clause", "2-clause bsd", "simplified bsd",
     "freebsd"): ("BSD-2-Clause",),
    ("gplv3", "gpl v3", "gpl-3", "gpl3", "gpl 3", "gpl-3.0", "gnu gpl v3", "gpl version 3"):
        ("GPL-3.0-only", "GPL-3.0-or-later"),
    ("gplv2", "gpl v2", "gpl-2", "gpl2", "gpl 2", "gpl-2.0", "gnu gpl v2", "gpl version 2"):
        ("GPL-2.0-only", "GPL-2.0-or-later"),
    ("lgplv3", "lgpl v3", "lgpl-3", "lgpl3", "lgpl-3.0"): ("LGPL-3.0-only", "LGPL-3.0-or-later"),
    ("lgplv2.1", "lgpl v2.1", "lgpl-2.1", "lgpl2.1"): ("LGPL-2.1-only", "LGPL-2.1-or-later"),
    ("mpl 2.0", "mpl2", "mpl-2", "mpl2.0", "mozilla public license 2.0"): ("MPL-2.0",),
    ("epl 2.0", "epl2", "epl-2", "eclipse public license 2.0"): ("EPL-2.0",),
    ("boost software license", "boost software license 1.0", "boost 1.0"): ("BSL-1.0",),
}
_SPDX = {alias: ids for aliases, ids in _ALIASES.items() for alias in aliases}


@rule("MAN019", "non-spdx-license", Severity.INFO, default_enabled=False,
      fix="Write the SPDX license identifier")
def non_spdx_license(package: Package) -> Iterator[Hit]:
    """A ``<license>`` spells a well-known license in a way that is not its SPDX identifier.

    ## What it does
    Reports license names that unambiguously denote one SPDX license, or an ``-only`` /
    ``-or-later`` pair (``Apache License 2.0``, ``GPLv3``, ``BSD 3-Clause``), with the
    identifier to use. Unknown, custom and ambiguous names such as ``BSD`` are left alone.
    This rule is off by default (many ROS 2 core packages write ``Apache License 2.0``);
    enable it with ``--select MAN019`` or ``extend-select``.

    ## Why is this bad?
    REP 149 leaves the string free, but license tooling (``ros2 pkg create``, bloom's copyright
    files, SBOM and compliance scanners) recognises SPDX identifiers only.

    ## Example
    ```xml
    <license>Apache License, Version 2.0</license>
    ```

    ## Use instead
    ```xml
    <license>Apache-2.0</license>
    ```
    """
    found = tree(package)
    if found is None:
        return
    for element in found.named("license"):
        ids = _SPDX.get(re.sub(r"\s+", " ", element.text.strip().lower()))
        if ids:
            written = " or ".join(f"`{i}`" for i in ids)
            yield Hit(element.span, f"License `{element.text}` is not an SPDX identifier",
                      f"Write {written}")
