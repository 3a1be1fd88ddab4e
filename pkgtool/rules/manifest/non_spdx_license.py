"""MAN019: a common license name written instead of its SPDX identifier (opt-in, info)."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.licenses import AMBIGUOUS, gnu_choices, spdx_expression, spdx_ids_for
from pkgtool.model.package import Package
from pkgtool.rules.manifest.common import tree
from pkgtool.rules.registry import rule


def spdx_spelling(text: str) -> str | None:
    """The SPDX way to write ``text`` when it is another spelling of a known license."""
    expression = spdx_expression(text)
    if expression is None:
        ids = spdx_ids_for(text)
        if len(ids) != 1 or " ".join(text.lower().split()) in AMBIGUOUS:
            return None
        expression = ids[0].replace("-only", "")  # an informal GPLv3 says neither -only nor +
    tokens = expression.replace("(", " ").replace(")", " ").split()
    for token in tokens:
        choices = gnu_choices(token)
        if choices:
            return " or ".join(f"`{expression.replace(token, choice)}`" for choice in choices)
    return f"`{expression}`" if expression != text.strip() else None


@rule("MAN019", "non-spdx-license", Severity.INFO, default_enabled=False,
      fix="Write the SPDX license identifier")
def non_spdx_license(package: Package) -> Iterator[Hit]:
    """A ``<license>`` spells a well-known license in a way that is not its SPDX identifier.

    ## What it does
    Reports license names that unambiguously denote one SPDX license, or an ``-only`` /
    ``-or-later`` pair (``Apache License 2.0``, ``GPLv3``, ``BSD 3-Clause``), SPDX identifiers
    and expressions in another case (``apache-2.0``, ``mit or apache-2.0``) and deprecated
    GNU identifiers (``GPL-3.0``, ``LGPL-2.1+``), with what to write. Every SPDX identifier is
    known (``packaging.licenses``); unknown, custom and ambiguous names such as ``BSD`` are
    left alone.
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
        suggestion = spdx_spelling(element.text)
        if suggestion:
            yield Hit(element.span, f"License `{element.text}` is not an SPDX identifier",
                      f"Write {suggestion}")
