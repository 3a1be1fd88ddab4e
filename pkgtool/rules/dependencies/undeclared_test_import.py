"""DEP003: a test imports a package that package.xml declares for neither tests nor run time."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.imports import (ANY, also_imported, declared, dependency_cause, grouped, needs,
                                   test_code)
from pkgtool.rules.registry import rule


@rule("DEP003", "undeclared-test-import", Severity.WARNING,
      fix="Add a `<test_depend>` for the imported package to package.xml")
def undeclared_test_import(package: Package) -> Iterator[Hit]:
    """A test module imports a package that package.xml does not declare.

    ## What it does
    Checks the unguarded absolute imports of test modules (files under `test/`, `test_*.py`,
    `*_test.py`, `conftest.py`) against every dependency of package.xml: `<test_depend>`, the
    run-time dependencies and the build dependencies all make a package available to
    `colcon test`. A module named like a test inside a Python package that colcon installs
    (a base class for other packages' tests) is installed code, checked by DEP001, unless
    pytest collects it and it defines a test (a test shipped by mistake).
    `ament_lint_common` brings the ament linters along (`ament_flake8`, `ament_pep257`,
    `ament_copyright`, ...), so a test importing them is covered by it. When the key is
    missing because package.xml misspells it as a run dependency, MAN021's finding lists the
    import instead (one mistake, one finding).

    ## Why is this bad?
    `rosdep install` (and the buildfarm's test jobs) install only declared dependencies, so
    the test run fails at collection on a clean machine, often hiding every other test.

    ## Example
    ```python
    import pytest  # package.xml has no <test_depend>python3-pytest</test_depend>
    ```

    ## Use instead
    ```xml
    <test_depend>python3-pytest</test_depend>
    ```
    """
    if package.manifest is None:
        return
    available = declared(package, ANY)
    unmet = (need for module in test_code(package) for need in needs(package, module)
             if need.kind != "unknown" and not any(k in available for k in need.keys))
    for need, others in grouped(unmet):
        yield Hit(need.imported.span,
                  f"`{need.top}` is imported by a test but {need.missing}" + also_imported(others),
                  f"Add `<test_depend>{need.key}</test_depend>` to package.xml",
                  related=tuple(other.imported.span for other in others),
                  cause=dependency_cause(need.key), consequence=True)
