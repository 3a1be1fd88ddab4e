"""The functions of a module that a call certainly runs (PYC013, PYC048), and how a call's
arguments bind to their parameters.

``self.name(...)`` in a plain method of a class runs the class's own ``def name`` when the
class body binds ``name`` once and no ``self.name`` is ever assigned, and so does
``x.name(...)`` where ``x`` certainly holds an instance of the class and the module assigns
no attribute ``name``; ``name(...)`` runs the
module's top-level ``def name`` (or constructs its ``class name``) when no scope around the
call binds ``name`` and the module binds it once.
"""

from __future__ import annotations

import ast

from pkgtool.model.ast_nodes import subtree
from pkgtool.model.memo import per_tree
from pkgtool.rules.node_api import unpacks
from pkgtool.rules.python._message_instances import binding_counts
from pkgtool.rules.scopes import COMPREHENSIONS, scope_bindings
from pkgtool.rules.syntax_trees import FUNCTIONS, Index

Function = ast.FunctionDef | ast.AsyncFunctionDef


@per_tree
def _definitions(scope: ast.Module | ast.ClassDef) -> dict[str, list[ast.stmt]]:
    """The functions and classes the body of ``scope`` defines, by name."""
    found: dict[str, list[ast.stmt]] = {}
    for statement in scope.body:
        if isinstance(statement, (*FUNCTIONS, ast.ClassDef)):
            found.setdefault(statement.name, []).append(statement)
    return found


@per_tree
def _stored_attributes(cls: ast.ClassDef | ast.Module) -> frozenset[str]:
    """The attribute names assigned or deleted anywhere in ``cls`` (``x.name = ...``)."""
    return frozenset(n.attr for n in subtree(cls)
                     if isinstance(n, ast.Attribute) and not isinstance(n.ctx, ast.Load))


@per_tree
def _from_imported(index: Index) -> frozenset[str]:
    """The names the module's ``from`` imports bind."""
    return frozenset(alias.asname or alias.name for node in index.import_froms
                     for alias in node.names)


def may_run_own(call: ast.Call, index: Index, tree: ast.Module) -> bool:
    """False when ``call`` certainly runs nothing the package defines: its callee is named
    like no function of the module (``self.get_logger()``), or like no definition or ``from``
    import there (``print()``). A cheap test before the others (most calls fail it)."""
    func = call.func
    if isinstance(func, ast.Attribute):
        return index.defines_function(func.attr)
    return isinstance(func, ast.Name) and \
        (func.id in _definitions(tree) or func.id in _from_imported(index))


def defined_once(scope: ast.Module | ast.ClassDef, name: str, kind: type = ast.FunctionDef
                 ) -> ast.AST | None:
    """The ``def name`` (or other definition of ``kind``) of the body of ``scope``, when
    nothing else there binds ``name``."""
    defs = _definitions(scope).get(name, ())
    if len(defs) != 1 or scope_bindings(scope)[name] != 1 or not isinstance(defs[0], kind):
        return None
    return defs[0]


def own_method(call: ast.Call, index: Index) -> tuple[ast.FunctionDef, ast.ClassDef] | None:
    """The method ``self.name()`` calls, found in the caller's class, when nothing rebinds it;
    with that class."""
    func = call.func
    cls = index.enclosing_class(call)
    outer = index.functions_around(call)[-1:] if cls is not None else []
    if not outer or not isinstance(func, ast.Attribute) or not isinstance(func.value, ast.Name) \
            or index.parents.get(id(outer[0])) is not cls or outer[0].decorator_list:
        return None
    positional = [*outer[0].args.posonlyargs, *outer[0].args.args]
    if not positional or positional[0].arg != func.value.id:
        return None
    assert cls is not None
    method = None if func.attr in _stored_attributes(cls) else defined_once(cls, func.attr)
    return (method, cls) if isinstance(method, ast.FunctionDef) else None


def instance_method(call: ast.Call, index: Index, tree: ast.Module
                    ) -> tuple[ast.FunctionDef, ast.ClassDef] | None:
    """The method ``x.name()`` calls where ``x`` certainly holds an instance of a class of the
    module (:func:`_instance_class`), found in that class, when nothing in the module assigns
    an attribute ``name``; with that class."""
    func = call.func
    if not (isinstance(func, ast.Attribute) and isinstance(func.value, ast.Name)) or \
            index.enclosing_class(call) is not None and index.enclosing_function(call) is None:
        return None
    scope = index.enclosing_function(call, through_lambdas=False)
    if scope is None and index.functions_around(call):
        return None  # inside a lambda: its parameters may shadow the name
    name = _instance_class(scope or tree, func.value.id, index)
    cls = defined_once(tree, name, ast.ClassDef) if name else None
    if not isinstance(cls, ast.ClassDef) or rebound_around(call, cls.name, index) or \
            func.attr in _stored_attributes(tree):
        return None
    method = defined_once(cls, func.attr)
    return (method, cls) if isinstance(method, ast.FunctionDef) else None


def _instance_class(scope: ast.AST, name: str, index: Index) -> str | None:
    """The class ``name`` is an instance of in ``scope``, when ``scope`` (and every scope in
    it) binds ``name`` once: as a parameter annotated with a class name (``node:
    Talker``), or by ``name = Class(...)`` in the scope's own code."""
    if binding_counts(scope)[name] != 1:
        return None
    if isinstance(scope, FUNCTIONS):
        arguments = scope.args
        for parameter in (*arguments.posonlyargs, *arguments.args, *arguments.kwonlyargs):
            if parameter.arg == name:
                note = parameter.annotation
                return note.id if isinstance(note, ast.Name) else None
    for node in subtree(scope):
        if isinstance(node, ast.Assign) and len(node.targets) == 1 and \
                isinstance(node.targets[0], ast.Name) and node.targets[0].id == name:
            value = node.value
            own = index.enclosing_function(node, through_lambdas=False) is (
                scope if isinstance(scope, FUNCTIONS) else None)
            return value.func.id if own and isinstance(value, ast.Call) and \
                isinstance(value.func, ast.Name) else None
    return None


def own_definition(call: ast.Call, index: Index, tree: ast.Module,
                   kind: type = ast.FunctionDef) -> ast.AST | None:
    """The module-level function (or class, by ``kind``) ``name()`` calls, when no scope
    around the call rebinds it."""
    func = call.func
    if not isinstance(func, ast.Name):
        return None
    found = defined_once(tree, func.id, kind)
    return found if found is not None and not rebound_around(call, func.id, index) else None


def rebound_around(node: ast.AST, name: str, index: Index) -> bool:
    """True when a scope around ``node`` binds ``name`` (a module-level name read there may
    stand for something else): a function whose body holds it, a lambda's parameters, a
    comprehension's targets (not in its first iterable, read outside it), or the class whose
    body holds ``node`` itself (not in a method, nor in a class nested in it: neither sees the
    class's names). A function's decorators, defaults and annotations, and a class's bases,
    are read in the scope around them."""
    below, child, parent = None, node, index.parents.get(id(node))
    past_a_scope = False
    while parent is not None:
        if isinstance(parent, FUNCTIONS) and any(child is s for s in parent.body):
            past_a_scope = True
            if scope_bindings(parent)[name]:
                return True
        elif isinstance(parent, ast.Lambda) and child is parent.body:
            past_a_scope = True
            if name in parameter_names(parent.args):
                return True
        elif isinstance(parent, COMPREHENSIONS) and not (
                child is parent.generators[0] and below is parent.generators[0].iter):
            if any(isinstance(n, ast.Name) and n.id == name
                   for g in parent.generators for n in ast.walk(g.target)):
                return True
        elif isinstance(parent, ast.ClassDef) and any(child is s for s in parent.body):
            if not past_a_scope and scope_bindings(parent)[name]:
                return True
            past_a_scope = True
        below, child, parent = child, parent, index.parents.get(id(parent))
    return False


def parameter_names(arguments: ast.arguments) -> set[str]:
    """The names of every parameter ``arguments`` declares."""
    return {a.arg for a in (*arguments.posonlyargs, *arguments.args, *arguments.kwonlyargs,
                            arguments.vararg, arguments.kwarg) if a is not None}


def missing_parameter(call: ast.Call, function: Function, skipped: int) -> str | None:
    """The first required parameter of ``function`` that ``call`` gives no value for (after
    the ``skipped`` receiver), when the call passes no ``*args``/``**kwargs``."""
    if unpacks(call):
        return None
    arguments = function.args
    positional = [*arguments.posonlyargs, *arguments.args][skipped:]
    required = positional[:len(positional) - len(arguments.defaults)]
    given = {k.arg for k in call.keywords}
    found = next((a.arg for a in required[len(call.args):] if a.arg not in given), None)
    if found is not None:
        return found
    return next((a.arg for a, default in zip(arguments.kwonlyargs, arguments.kw_defaults)
                 if default is None and a.arg not in given), None)


def binding_error(call: ast.Call, function: Function, skipped: int) -> str | None:
    """What Python's TypeError would say about binding ``call``'s arguments to ``function``
    (after the ``skipped`` receiver), in words of our own; None when they bind (or the call
    passes ``*args``/``**kwargs``)."""
    if unpacks(call):
        return None
    arguments = function.args
    positional = [*arguments.posonlyargs, *arguments.args][skipped:]
    if len(call.args) > len(positional) and arguments.vararg is None:
        most = len(positional)
        return (f"it gives {len(call.args)} positional argument{'s' * (len(call.args) != 1)} "
                f"where the function takes {most or 'none'}")
    names = {a.arg for a in positional[max(0, len(arguments.posonlyargs) - skipped):]} | \
        {a.arg for a in arguments.kwonlyargs}
    taken = {a.arg for a in positional[:len(call.args)]}
    for keyword in call.keywords:
        if keyword.arg in taken:
            return f"it gives `{keyword.arg}` by position and again by keyword"
        if keyword.arg not in names and arguments.kwarg is None:
            return f"the function has no parameter `{keyword.arg}`"
    missing = missing_parameter(call, function, skipped)
    return f"it leaves out `{missing}`, which the function requires" if missing else None
