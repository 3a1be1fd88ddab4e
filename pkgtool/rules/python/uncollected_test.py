"""PYC012: a file under test/ defines tests that pytest never collects."""

from __future__ import annotations

import ast
import posixpath
import re
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.installed import is_ament_python
from pkgtool.model.package import Package
from pkgtool.model.pytest_config import PytestConfig, pytest_config
from pkgtool.model.python_visitor import parse_tree
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule
from pkgtool.rules.test_modules import first_test, why_not_collected


def _read_by_other_tests(package: Package, path: str) -> bool:
    """True when another test file names this file, or a folder holding it, in a string.

    Such files are test data: another test runs them itself (pytester, launch_testing).
    """
    parts = path.split("/")
    words = {*parts[1:-1], parts[-1], parts[-1][:-3]}
    found = re.compile("|".join(rf"['\"/]{re.escape(w)}['\"/.]" for w in words))
    return any(other != path and other.split("/")[0] == parts[0] and found.search(text)
               for other, text in package.texts.items() if other.endswith(".py"))


def _explicit_arguments(package: Package, config: PytestConfig) -> bool:
    """True when ``addopts`` names a file or folder: pytest then collects just what it names."""
    return any(not a.startswith("-") and (package.has_file(a.rstrip("/")) or any(
        f.startswith(a.rstrip("/") + "/") for f in package.files)) for a in config.get("addopts"))


@rule("PYC012", "uncollected-test", Severity.WARNING,
      fix="Name the file `test_<name>.py`, or change the pytest setting that leaves it out")
def uncollected_test(package: Package) -> Iterator[Hit]:
    """A file under `test/` defines tests that pytest never collects.

    ## What it does
    Finds Python files under `test/` or `tests/` of an ament_python package that define a
    test (a top-level `test*` function, or a `Test*` class or `unittest.TestCase` with
    `test*` methods) that `colcon test` never runs: pytest, started in the package folder
    without arguments, does not collect the file because its name matches no `python_files`
    pattern (`test_*.py`, `*_test.py` by default), `testpaths` leaves it out, or a
    `norecursedirs` pattern skips its folder. These settings are read from the file pytest
    uses: `pytest.ini`, `pyproject.toml` (`[tool.pytest.ini_options]`), `tox.ini` or
    `setup.cfg` (`[tool:pytest]`); `python_functions` and `python_classes` are honoured too.
    A configuration that does not parse, or `addopts` naming paths, leaves the rule silent,
    and so does a file that another test names in a string (its name, or a folder holding
    it): test data that the other test runs itself (pytester, launch_testing).

    ## Why is this bad?
    The tests never run, and `colcon test` reports success: the checks they were written
    for are silently lost.

    ## Example
    ```text
    test/speed_limits.py    # def test_limits(): ...
    ```

    ## Use instead
    ```text
    test/test_speed_limits.py
    ```
    """
    config = pytest_config(package)
    if config is None or not is_ament_python(package) or _explicit_arguments(package, config):
        return
    for module in package.modules:
        path = module.path
        if path.split("/")[0] not in ("test", "tests") or module.syntax_error or \
                posixpath.basename(path) in ("conftest.py", "__init__.py"):
            continue
        reason = why_not_collected(package, path, config)
        tree = parse_tree(path, package.texts[path]) if reason else None
        test = first_test(tree, config) if isinstance(tree, ast.Module) else None
        if reason and test is not None and not _read_by_other_tests(package, path):
            yield Hit(Span(path, test.lineno, test.col_offset + 1),
                      f"pytest does not collect `{path}`, so its tests never run: {reason}")
