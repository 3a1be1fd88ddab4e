"""SET007: test dependencies given only as tests_require."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.installed import keyword_known
from pkgtool.model.package import Package
from pkgtool.rules.registry import rule
from pkgtool.rules.setup_values import checked_setup

TEST_EXTRAS = ("test", "tests", "testing")
"""extras_require keys colcon reads as test dependencies."""


@rule("SET007", "tests-require", Severity.INFO,
      fix="Replace `tests_require=[...]` with `extras_require={'test': [...]}`")
def tests_require(package: Package) -> Iterator[Hit]:
    """Test dependencies are declared with `tests_require` and no `test` extra.

    ## What it does
    Reports `setup(tests_require=...)` when `extras_require` has no `test` (or `tests`,
    `testing`) extra.

    ## Why is this bad?
    colcon decides to run pytest when pytest is a test dependency, read from `tests_require`
    or the `test` extra. setuptools 72 and newer no longer know `tests_require` ("Unknown
    distribution option"), so with such a setuptools `colcon test` falls back to unittest,
    reports "Ran 0 tests ... OK" and a stale pytest.xml keeps showing old results. It still
    works with Ubuntu 24.04's setuptools 68 (and Jazzy's own `ros2 pkg create` writes it),
    hence only an info.

    ## Example
    ```python
    setup(..., tests_require=['pytest'])
    ```

    ## Use instead
    ```python
    setup(..., extras_require={'test': ['pytest']})
    ```

    ## References
    - https://github.com/ament/ament_package/issues/157 ("Ran 0 tests" with setuptools 75)
    - https://setuptools.pypa.io/en/stable/history.html#v72-0-0
    """
    setup = checked_setup(package)
    if setup is None or setup.tests_require is None or not keyword_known(package,
                                                                         "extras_require"):
        return
    extras = setup.extras_require.value if setup.extras_require else {}
    if isinstance(extras, dict) and any(key in extras for key in TEST_EXTRAS):
        return
    yield Hit(setup.tests_require.span,
              "`tests_require` is ignored by setuptools 72 and newer: `colcon test` then runs "
              "no pytest tests")
