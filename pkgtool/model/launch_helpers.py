"""Functions of a launch file that look a package up by a name they are given.

The MoveIt tutorials' launch files define ``load_yaml(package_name, file_path)``, whose body
calls ``get_package_share_directory(package_name)``: ``load_yaml('panda_moveit_config',
'kinematics.yaml')`` looks ``panda_moveit_config`` up in the ament index as surely as a
direct call would.
"""

from __future__ import annotations

import ast
from collections.abc import Collection

from pkgtool.model.ast_nodes import TRIES, enclosing, last_name, nodes_of_class, walk_once
from pkgtool.records import record


@record
class PackageParameter:
    """The parameter of a function that names the package it looks up: its position among
    the positional parameters and its name (for a keyword argument)."""

    position: int
    name: str


def package_parameters(tree: ast.Module, lookups: Collection[str]
                       ) -> dict[str, PackageParameter]:
    """The module-level functions of ``tree`` (each defined once, at the top level) whose
    body passes one of their parameters, never rebound, straight to one of ``lookups``
    (``get_package_share_directory(package_name)``), by function name."""
    defined: dict[str, list[ast.FunctionDef]] = {}
    for statement in tree.body:
        if isinstance(statement, ast.FunctionDef):
            defined.setdefault(statement.name, []).append(statement)
    found: dict[str, PackageParameter] = {}
    for name, functions in defined.items():
        parameter = _package_parameter(functions[0], lookups) if len(functions) == 1 else None
        if parameter is not None:
            found[name] = parameter
    return found


def _package_parameter(function: ast.FunctionDef, lookups: Collection[str]
                       ) -> PackageParameter | None:
    """The parameter ``function`` looks a package up by, unless the lookup stands in a
    ``try`` (a helper asking whether the package is installed, not needing it)."""
    positional = [a.arg for a in (*function.args.posonlyargs, *function.args.args)]
    stored = {n.id for n in nodes_of_class(function, ast.Name)
              if isinstance(n, ast.Name) and not isinstance(n.ctx, ast.Load)}
    parents = walk_once(function).parents
    for call in nodes_of_class(function, ast.Call):
        first = call.args[0] if isinstance(call, ast.Call) and call.args and \
            last_name(call.func) in lookups else None
        if isinstance(first, ast.Name) and first.id in positional and \
                first.id not in stored and enclosing(call, parents, TRIES) is None:
            return PackageParameter(positional.index(first.id), first.id)
    return None


def package_argument(call: ast.Call, parameter: PackageParameter) -> ast.expr | None:
    """The argument ``call`` gives the function's package parameter, if it gives one."""
    keyword = next((k.value for k in call.keywords if k.arg == parameter.name), None)
    if keyword is not None:
        return keyword
    if any(isinstance(a, ast.Starred) for a in call.args[:parameter.position + 1]):
        return None
    return call.args[parameter.position] if parameter.position < len(call.args) else None
