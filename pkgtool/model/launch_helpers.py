"""Functions of a launch file that look a package up by a name they are given.

The MoveIt tutorials' launch files define ``load_yaml(package_name, file_path)``, whose body
calls ``get_package_share_directory(package_name)`` first thing: ``load_yaml(
'panda_moveit_config', 'kinematics.yaml')`` looks ``panda_moveit_config`` up in the ament
index as surely as a direct call would. Only helpers that certainly do are taken: defined
once at the top of the module, undecorated, their name never bound anywhere else in the
module (no inner function, parameter, ``partial`` or import can stand for it), and making
the lookup on every call (not under an ``if``, a loop, a ``try`` or an expression that may
skip it, nor after a ``return`` or ``raise`` that may end the call first).
"""

from __future__ import annotations

import ast
from collections.abc import Collection

from pkgtool.model.ast_nodes import last_name, names_bound_by, nodes_of_class, walk_once
from pkgtool.records import record

_CONDITIONAL = (ast.If, ast.IfExp, ast.BoolOp, ast.For, ast.AsyncFor, ast.While, ast.Try,
                ast.With, ast.AsyncWith, ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda,
                ast.ListComp, ast.SetComp, ast.DictComp, ast.GeneratorExp, ast.Match,
                *((ast.TryStar,) if hasattr(ast, "TryStar") else ()))
"""Nodes whose parts may not run on every pass through them."""


@record
class PackageParameter:
    """The parameter of a function that names the package it looks up: its position among
    the positional parameters, its name (for a keyword argument), and whether the lookup is a
    substitution (``FindPackageShare``: made when the action holding it runs)."""

    position: int
    name: str
    substitution: bool


def package_parameters(tree: ast.Module, lookups: Collection[str],
                       substitutions: Collection[str]) -> dict[str, PackageParameter]:
    """The module-level helpers of ``tree`` that certainly look a package up by one of their
    parameters (see the module's docstring), by function name."""
    found: dict[str, PackageParameter] = {}
    for statement in tree.body:
        if isinstance(statement, ast.FunctionDef) and not statement.decorator_list:
            parameter = _package_parameter(statement, lookups, substitutions)
            if parameter is not None:
                found[statement.name] = parameter
    if not found:
        return found  # most launch files: counting every binding is spared
    bound: dict[str, int] = {}
    for node in walk_once(tree).nodes:
        for name in names_bound_by(node):
            bound[name] = bound.get(name, 0) + 1
    return {name: parameter for name, parameter in found.items() if bound.get(name) == 1}


def _package_parameter(function: ast.FunctionDef, lookups: Collection[str],
                       substitutions: Collection[str]) -> PackageParameter | None:
    """The parameter ``function`` certainly looks a package up by, if one."""
    positional = [a.arg for a in (*function.args.posonlyargs, *function.args.args)]
    if not positional:
        return None  # generate_launch_description()
    stored = {n.id for n in nodes_of_class(function, ast.Name)
              if isinstance(n, ast.Name) and not isinstance(n.ctx, ast.Load)}
    parents = walk_once(function).parents
    for call in nodes_of_class(function, ast.Call):
        first = call.args[0] if isinstance(call, ast.Call) and call.args and \
            last_name(call.func) in lookups else None
        if isinstance(first, ast.Name) and first.id in positional and \
                first.id not in stored and _always_made(call, function, parents):
            return PackageParameter(positional.index(first.id), first.id,
                                    last_name(call.func) in substitutions)  # type: ignore
    return None


def _always_made(call: ast.AST, function: ast.FunctionDef, parents: dict[int, ast.AST]
                 ) -> bool:
    """True when every call of ``function`` reaches ``call``: nothing around it may skip it,
    and no statement before the one holding it may return or raise."""
    child, parent = call, parents.get(id(call))
    while parent is not None and parent is not function:
        if isinstance(parent, _CONDITIONAL):
            return False
        child, parent = parent, parents.get(id(parent))
    for statement in function.body:
        if statement is child:
            return True
        if any(isinstance(n, (ast.Return, ast.Raise)) for n in ast.walk(statement)):
            return False
    return False


def package_argument(call: ast.Call, parameter: PackageParameter) -> ast.expr | None:
    """The argument ``call`` gives the function's package parameter, if it gives one."""
    keyword = next((k.value for k in call.keywords if k.arg == parameter.name), None)
    if keyword is not None:
        return keyword
    if any(isinstance(a, ast.Starred) for a in call.args[:parameter.position + 1]):
        return None
    return call.args[parameter.position] if parameter.position < len(call.args) else None
