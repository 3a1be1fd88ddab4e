"""PYC010: a standard library module that the target distribution's Python does not have."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rosdistro import (PYTHON_VERSIONS, STDLIB_VERSIONS, any_stdlib_module,
                                         keys_for_import, stdlib_modules, stdlib_versions)
from pkgtool.model.package import Package
from pkgtool.rules.imports import all_python, local_modules
from pkgtool.rules.registry import rule
from pkgtool.rules.ros1_platform import is_ros1_package

_VERSIONS = STDLIB_VERSIONS
_INSTEAD = {"imp": "`importlib`",
            "asyncore": "`asyncio`", "asynchat": "`asyncio`", "smtpd": "`aiosmtpd`"}
"""What replaces a removed module (the "What's New" of the release that removed it)."""


def _why(module: str, version: str) -> tuple[str, str]:
    """The reason and the fix for ``module`` missing from Python ``version``."""
    history = stdlib_versions(module)
    target = _VERSIONS.index(version)
    older = [v for v in history if _VERSIONS.index(v) < target]
    if not older:
        return (f"it is new in Python {history[0]}",
                f"Do without `{module}` (or a backport from PyPI) on this distribution")
    gone = _VERSIONS[_VERSIONS.index(older[-1]) + 1]
    return (f"it was removed in Python {gone}",
            f"Use {_INSTEAD.get(module, 'its replacement')} instead of `{module}`")


_SHIMMED = "distutils"
"""Removed from Python 3.12, but setuptools' ``distutils-precedence.pth`` provides it to every
Python process of a machine with setuptools, which every ROS 2 install has (colcon, ament)."""


_TEST_MODULES = ("_test", "xx", "_xx", "_ctypes_test")
"""How the names of CPython's test and example extension modules begin (``_testcapi``,
``xxlimited``, ``xxsubtype``): builds still ship them (Debian's ``libpython3.12-stdlib``), but
the lists stdlib-list reads from 3.10 on leave test modules out, so the table cannot tell."""


@rule("PYC010", "stdlib-module-not-on-target", Severity.ERROR,
      fix="Use a module that the target distribution's Python has")
def stdlib_module_not_on_target(package: Package) -> Iterator[Hit]:
    """A standard library module is imported that the target's Python does not have.

    ## What it does
    Checks unguarded imports of every Python file against the standard library of the
    target distribution's Python (humble 3.10, jazzy 3.12, kilted and rolling 3.12; set the
    distribution with `--rosdistro` or `rosdistro` in `[tool.pkgtool]`), not of the Python
    running pkgtool: a module that some Python 3 has in its standard library but the target's
    has not, either removed (`imp`, `asyncore` in 3.12) or newer (`tomllib` on
    humble). Module lists come from a table generated from the stdlib-list package. Imports
    inside `try/except ImportError` are alternatives and stay silent, and so are imports of the
    package's own modules named like one (a `test/` package the tests import as `test.support`,
    which pytest's import mode puts on `sys.path`), and `distutils`: setuptools, which every
    ROS 2 install has (colcon and ament build with it), provides it to every Python process
    through its `distutils-precedence.pth` shim, Python 3.12 included; nor CPython's test
    and example extension modules (`_testcapi`, `xxlimited`, `xxsubtype`), which builds still
    ship though the module lists of 3.10 on leave them out. In a ROS 1 (catkin)
    package only modules newer than the target's Python are reported: Noetic's Python 3.8
    still has the removed ones.

    ## Why is this bad?
    The node fails with `ModuleNotFoundError` on the robot's Python although it ran on the
    developer's.

    ## Example
    ```python
    import imp  # jazzy: Python 3.12 has no imp
    ```

    ## Use instead
    ```python
    import importlib
    ```
    """
    distro = package.context.distro
    version = PYTHON_VERSIONS[distro]
    here = stdlib_modules(distro)
    known = any_stdlib_module()
    ros1 = is_ros1_package(package)
    for module in all_python(package):
        seen: set[str] = set(local_modules(package, module))
        for imported in module.imports:
            top = imported.top_level
            if (not top or top in seen or imported.guarded or top in here or top not in known
                    or keys_for_import(top, distro)
                    or top == _SHIMMED or top.startswith(_TEST_MODULES)):
                continue
            seen.add(top)
            why, fix = _why(top, version)
            if ros1 and why.startswith("it was removed"):
                continue  # Noetic's Python 3.8 still has it (see pkgtool.rules.ros1_platform)
            yield Hit(imported.span, f"`{top}` is not in the standard library of Python "
                      f"{version} ({distro}): {why}", fix)
