"""SET002: setup.py that never calls setup()."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.installed import is_ament_python
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule


@rule("SET002", "missing-setup-call", Severity.ERROR,
      fix="Call `setup(...)` from `setuptools` in `setup.py`")
def missing_setup_call(package: Package) -> Iterator[Hit]:
    """setup.py contains no `setup(...)` call at all.

    ## What it does
    Reports a setup.py (that parses) in which no call named `setup` appears anywhere, in a
    package colcon builds with it (not a CMake package's leftover file, which nothing runs).

    ## Why is this bad?
    Running such a setup.py installs nothing: colcon reports the build as done, yet the
    package has no modules, no console scripts and no ament index entry.

    ## Example
    ```python
    from setuptools import setup

    package_name = 'my_pkg'
    ```

    ## Use instead
    ```python
    from setuptools import setup

    package_name = 'my_pkg'
    setup(name=package_name, version='0.1.0', packages=[package_name])
    ```
    """
    setup = package.setup_py
    if setup is not None and setup.setup_span is None and is_ament_python(package):
        yield Hit(Span(setup.path, 1, 1), "`setup.py` never calls `setup()`")
