"""SET004: setup.py's version differs from package.xml's."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.registry import rule
from pkgtool.rules.setup_values import beside_manifest


@rule("SET004", "setup-version-mismatch", Severity.WARNING,
      fix="Give `setup(version=...)` the `<version>` of `package.xml`")
def setup_version_mismatch(package: Package) -> Iterator[Hit]:
    """`setup(version=...)` is not the version in package.xml.

    ## What it does
    Compares the statically known `version` keyword of `setup()` with package.xml's
    `<version>`.

    ## Why is this bad?
    bloom and the build farm release the package.xml version, while the installed Python
    distribution carries setup.py's: users and `pip list` see a version that was never released.

    ## Example
    ```python
    setup(name='my_pkg', version='0.0.0', ...)   # package.xml: <version>1.2.0</version>
    ```

    ## Use instead
    ```python
    setup(name='my_pkg', version='1.2.0', ...)
    ```
    """
    found = beside_manifest(package, "version")
    if found and found[0].strip() != found[2]:
        version, span, wanted = found
        yield Hit(span, f"`setup.py` version `{version}` differs from the `package.xml` version "
                        f"`{wanted}`")
