"""The modules whose rclpy calls fail at run time: installed code, then the tests."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.model.modules import PythonModule
from pkgtool.model.package import Package
from pkgtool.rules.syntax_trees import Index, index_of, installed_trees
from pkgtool.rules.test_modules import test_trees


def code_and_test_indexes(package: Package) -> Iterator[tuple[PythonModule, Index]]:
    """The installed modules, then the test modules, each with the index of its tree."""
    installed = installed_trees(package)
    yield from ((module, index) for module, _, index in installed)
    done = {module.path for module, _, _ in installed}
    modules = {module.path: module for module in package.modules if module.path not in done}
    for path, tree in test_trees(package):
        if path in modules:
            yield modules[path], index_of(tree)
