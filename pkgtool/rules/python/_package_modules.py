"""The installed modules of a package by dotted name, and what a name imported from one of
them stands for (PYC048, PYC064): ``from .vision import Processor`` in ``my_pkg/talker.py``
is ``my_pkg.vision.Processor``."""

from __future__ import annotations

import ast

from pkgtool.model.memo import per_package
from pkgtool.model.package import Package
from pkgtool.rules.imports import absolute_module, installed_names, python_package_of
from pkgtool.rules.scopes import scope_bindings
from pkgtool.rules.syntax_trees import Index, installed_trees


@per_package
def module_names(package: Package) -> dict[int, tuple[str, str]]:
    """The dotted name of each installed module and of the Python package it is in, by the
    id of its index."""
    names = installed_names(package)
    return {id(index): (names[module.path], python_package_of(package, module))
            for module, _, index in installed_trees(package) if names.get(module.path)}


@per_package
def modules_by_name(package: Package) -> dict[str, tuple[ast.Module, Index]]:
    """The tree and index of each installed module by its dotted name."""
    names = module_names(package)
    return {names[id(index)][0]: (tree, index) for _, tree, index in installed_trees(package)
            if id(index) in names}


def imported_from_package(name: str, tree: ast.Module, index: Index, package: Package
                          ) -> tuple[str, str] | None:
    """(module, name in it) for a name of the module of ``tree`` bound only by one ``from``
    import (absolute or relative) of an installed module of the package."""
    where = module_names(package).get(id(index))
    if where is None or scope_bindings(tree)[name] != 1:
        return None
    found = [(absolute_module(node.module, node.level, where[1]), alias.name)
             for node in index.import_froms
             for alias in node.names if (alias.asname or alias.name) == name]
    return found[0] if len(found) == 1 and found[0][0] in modules_by_name(package) else None
