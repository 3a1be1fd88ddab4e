"""SET006: setup.py's maintainer is not among package.xml's maintainers."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.registry import rule
from pkgtool.rules.setup_values import checked_setup, same_text, text_of
from pkgtool.lazy_regex import lazy_pattern

_ADDRESSED = lazy_pattern(r"\s*(?P<name>[^<>]*?)\s*<\s*(?P<address>[^<>]*?)\s*>\s*")
"""A person written as ``Name <address>`` (or ``<address>`` alone)."""


def _people(text: str) -> list[tuple[str, str | None]]:
    """(name, address) of each comma-separated person in ``text``; a ``<address>`` part is
    split off the name (an empty name when only the address is given), else it is None."""
    found = []
    for part in [p for p in text.split(",") if p.strip()] or [text]:
        match = _ADDRESSED.fullmatch(part)
        found.append((match["name"], match["address"]) if match else (part, None))
    return found


@rule("SET006", "setup-maintainer-mismatch", Severity.INFO,
      fix="Use a `<maintainer>` of `package.xml` (name and email) in `setup()`")
def setup_maintainer_mismatch(package: Package) -> Iterator[Hit]:
    """`setup(maintainer=..., maintainer_email=...)` matches no package.xml maintainer.

    ## What it does
    Compares the statically known `maintainer` and `maintainer_email` with the names and
    emails of package.xml's `<maintainer>` tags; matching any one maintainer is enough, and a
    comma-separated list in setup.py matches when one of its names does (or the whole text,
    for a name with a comma: `Stanley Innovation, Inc.`). A person written
    with the address, `'Ada Lovelace <ada@example.com>'`, is compared by the name (by the
    address when only `<ada@example.com>` is given): the address is not part of the name.

    ## Why is this bad?
    The Python metadata names someone package.xml does not: usually a template default or a
    previous maintainer who no longer answers for the package.

    ## Example
    ```python
    setup(maintainer='root', maintainer_email='root@todo.todo', ...)
    ```

    ## Use instead
    ```python
    setup(maintainer='Ada Lovelace', maintainer_email='ada@example.com', ...)
    ```
    """
    setup = checked_setup(package)
    manifest = package.manifest
    if setup is None or manifest is None or not manifest.maintainers:
        return
    names = [p.name for p in manifest.maintainers]
    emails = [p.email or "" for p in manifest.maintainers]
    checks = ((setup.maintainer, "maintainer", names), (setup.maintainer_email,
                                                        "maintainer_email", emails))
    for value, keyword, declared in checks:
        found = text_of(value)
        if found is None or not any(declared):
            continue
        text, span = found
        if not any(_same_person(name, address, keyword, names, emails)
                   for name, address in [*_people(text), (text, None)]):  # whole: "Acme, Inc."
            shown = ", ".join(f"`{d}`" for d in declared if d)
            yield Hit(span, f"`{keyword}` `{text}` is not a `package.xml` maintainer ({shown})")


def _same_person(name: str, address: str | None, keyword: str, names: list[str],
                 emails: list[str]) -> bool:
    """Whether one person of ``keyword`` is a package.xml maintainer: a ``maintainer`` by the
    name, a ``maintainer_email`` or a ``maintainer`` given only as ``<address>`` by the
    address."""
    if keyword == "maintainer" and name:
        return any(same_text(name, d) for d in names)
    given = address if address is not None else name
    return any(same_text(given, e) for e in emails if e)
