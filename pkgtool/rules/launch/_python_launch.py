"""What the rules on Python launch files share: the function's name, the launch classes calls
make (which files they read: :func:`pkgtool.rules.syntax_trees.launch_indexes`)."""

from __future__ import annotations

import ast
from collections.abc import Iterable, Iterator

from pkgtool.model.ast_nodes import subtree
from pkgtool.model.launch import LaunchFile, is_launch_test, parse_launch
from pkgtool.model.memo import per_package
from pkgtool.model.package import Package
from pkgtool.rules.scopes import single_assignments
from pkgtool.rules.syntax_trees import Index, launch_indexes

FUNCTION = "generate_launch_description"
"""The function ``ros2 launch`` calls in a Python launch file."""


def text_argument(call: ast.Call, keyword: str) -> str | None:
    """The first argument (or ``keyword``) of a call, when it is a string literal (the name a
    ``DeclareLaunchArgument`` declares, a ``LaunchConfiguration`` reads)."""
    value = call.args[0] if call.args else next(
        (k.value for k in call.keywords if k.arg == keyword), None)
    return value.value if isinstance(value, ast.Constant) and isinstance(value.value, str) \
        else None


def within(module: str, homes: tuple[str, ...]) -> bool:
    """True when ``module`` is one of ``homes`` or a submodule of one."""
    return any(module == home or module.startswith(home + ".") for home in homes)


def launch_class(call: ast.Call, index: Index) -> tuple[str, str]:
    """The module and class a call of the module ``index`` describes makes when bound by an
    import (``launch.actions``, ``DeclareLaunchArgument``); ``("", "")`` for any other call."""
    module, _, name = (index.qualified(call.func) or "").rpartition(".")
    return (module, name) if module.split(".")[0] in ("launch", "launch_ros") else ("", "")


def own_nodes(function: ast.AST, index: Index) -> Iterator[ast.AST]:
    """The nodes of ``function``'s own body (those of a nested function are its own), in
    walk order."""
    return (node for node in subtree(function) if index.enclosing_function(node) is function)


def launch_function_nodes(package: Package
                          ) -> Iterator[tuple[str, Index, dict[str, ast.expr], ast.AST]]:
    """Each node of the own body of each function of the package's Python launch files, with
    the file's path and index and the names the function binds once, to their values
    (:func:`~pkgtool.rules.scopes.single_assignments`)."""
    for path, index in launch_indexes(package):
        for function in index.functions:
            single = single_assignments(function)
            for node in own_nodes(function, index):
                yield path, index, single, node


SUBSTITUTIONS = ("launch.substitutions", "launch_ros.substitutions")
"""The modules whose classes are all substitutions."""


def substitution_made(value: ast.expr, index: Index, single: dict[str, ast.expr]) -> str | None:
    """The substitution class ``value`` makes (directly, or through a name the function binds
    once, to it: ``single``), else None."""
    if isinstance(value, ast.Name) and value.id in single:
        value = single[value.id]
    if not isinstance(value, ast.Call):
        return None
    module, name = launch_class(value, index)
    return name if within(module, SUBSTITUTIONS) and name[:1].isupper() else None


def first_substitution(values: Iterable[ast.expr], index: Index, single: dict[str, ast.expr]
                       ) -> str | None:
    """The class of the first of ``values`` that is a substitution (:func:`substitution_made`),
    else None."""
    return next((made for value in values
                 if (made := substitution_made(value, index, single))), None)


@per_package
def launch_tests(package: Package) -> tuple[LaunchFile, ...]:
    """The package's ``launch_testing`` tests (modules defining ``generate_test_description``)
    read as Python launch files: the nodes they start, the packages they name."""
    return tuple(parse_launch(module.path, text) for module in package.modules
                 if (text := package.texts.get(module.path)) is not None and
                 is_launch_test(module.path, text))
