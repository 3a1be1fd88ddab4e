"""SET006: setup.py's maintainer is not among package.xml's maintainers."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.registry import rule
from pkgtool.rules.setup_values import checked_setup, same_text, text_of


@rule("SET006", "setup-maintainer-mismatch", Severity.INFO,
      fix="Use a `<maintainer>` of `package.xml` (name and email) in `setup()`")
def setup_maintainer_mismatch(package: Package) -> Iterator[Hit]:
    """`setup(maintainer=..., maintainer_email=...)` matches no package.xml maintainer.

    ## What it does
    Compares the statically known `maintainer` and `maintainer_email` with the names and
    emails of package.xml's `<maintainer>` tags; matching any one maintainer is enough, and a
    comma-separated list in setup.py matches when one of its names does.

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
    people = manifest.maintainers
    checks = ((setup.maintainer, "maintainer", [p.name for p in people]),
              (setup.maintainer_email, "maintainer_email", [p.email or "" for p in people]))
    for value, keyword, declared in checks:
        found = text_of(value)
        if found is None or not any(declared):
            continue
        text, span = found
        given = [part for part in text.split(",") if part.strip()] or [text]
        if not any(same_text(g, d) for g in given for d in declared):
            shown = ", ".join(f"`{d}`" for d in declared if d)
            yield Hit(span, f"`{keyword}` `{text}` is not a `package.xml` maintainer ({shown})")
