"""What the rules on Python launch files share: which files they read, the function's name,
the launch classes calls make."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.model.launch import LaunchFile, is_launch_test, parse_launch
from pkgtool.model.memo import per_package
from pkgtool.model.modules import PythonModule
from pkgtool.model.package import Package
from pkgtool.model.python_visitor import parse_tree
from pkgtool.rules.syntax_trees import Index, index_of

FUNCTION = "generate_launch_description"
"""The function ``ros2 launch`` calls in a Python launch file."""


def python_launch_files(package: Package) -> Iterator[tuple[str, PythonModule, str]]:
    """(path, module, text) of each Python launch file that parses and is not a test."""
    for launch in package.launch_files:
        module = launch.python
        text = package.texts.get(launch.path)
        if module is not None and not module.syntax_error and text is not None and \
                not module.is_test:
            yield launch.path, module, text


def launch_indexes(package: Package) -> Iterator[tuple[str, Index]]:
    """(path, index of its syntax tree) of each file :func:`python_launch_files` gives."""
    for path, _, text in python_launch_files(package):
        tree = parse_tree(path, text)
        if isinstance(tree, ast.Module):
            yield path, index_of(tree)


def within(module: str, homes: tuple[str, ...]) -> bool:
    """True when ``module`` is one of ``homes`` or a submodule of one."""
    return any(module == home or module.startswith(home + ".") for home in homes)


def launch_class(call: ast.Call, index: Index) -> tuple[str, str]:
    """The module and class a call of the module ``index`` describes makes when bound by an
    import (``launch.actions``, ``DeclareLaunchArgument``); ``("", "")`` for any other call."""
    module, _, name = (index.qualified(call.func) or "").rpartition(".")
    return (module, name) if module.split(".")[0] in ("launch", "launch_ros") else ("", "")


@per_package
def launch_tests(package: Package) -> tuple[LaunchFile, ...]:
    """The package's ``launch_testing`` tests (modules defining ``generate_test_description``)
    read as Python launch files: the nodes they start, the packages they name."""
    return tuple(parse_launch(module.path, text) for module in package.modules
                 if (text := package.texts.get(module.path)) is not None and
                 is_launch_test(module.path, text))
