"""A quick proof that a module uses no undefined name, so PYC001 can skip pyflakes for it.

:func:`every_name_defined` walks the tree in the order pyflakes does (the value of an
assignment before its targets, a loop's iterable before its target, the generators of a
comprehension before its element, function bodies after the whole module, each with the
scopes as they were where it was defined) and binds names exactly when pyflakes would, or
later. True means every loaded name was bound, in a scope pyflakes would look in, at the point
pyflakes checks it: pyflakes would report no undefined name. Whenever that cannot be told
simply (``global``, ``nonlocal``, ``del``, ``:=``, ``match``, star imports, names in strings
that pyflakes reads as annotations, unusual dunders), the answer is False and pyflakes decides.
A test holds the proof to pyflakes on every fixture, the reference packages, pkgtool itself
and mutants of them.
"""

from __future__ import annotations

import ast
import builtins
from collections import deque
from collections.abc import Callable
from functools import cache
from typing import Any

from pkgtool.model.ast_nodes import CHILD_FIELDS, descendants, nodes_of_class

_KNOWN = frozenset(dir(builtins)) | {"__file__", "__builtins__", "__annotations__",
                                     "WindowsError"}
"""Names pyflakes takes as defined everywhere (its builtins and magic globals)."""
_UNDECIDED = (ast.Global, ast.Nonlocal, ast.NamedExpr, ast.Match)
_TYPING = frozenset({"typing", "typing_extensions"})
_FUNCTIONS = (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)


class Undecided(Exception):
    """The module holds something the proof does not model."""


@cache
def _field_order(kind: type[ast.AST]) -> tuple[str, ...]:
    """The order pyflakes visits the fields of ``kind`` that may hold nodes in."""
    fields = CHILD_FIELDS[kind]
    first = "iter" if "iter" in fields else "generators" if "generators" in fields else "value"
    return tuple(sorted(fields, key=first.find, reverse=True))


class _Scope(set[str]):
    """The names bound so far in one scope."""

    def __init__(self, is_class: bool = False) -> None:
        super().__init__()
        self.is_class = is_class


class _Walk:
    def __init__(self) -> None:
        self.stack: list[_Scope] = [_Scope()]
        self.deferred: deque[tuple[ast.AST, list[_Scope]]] = deque()

    def run(self, tree: ast.Module) -> None:
        for statement in tree.body:
            self.visit(statement)
        while self.deferred:
            function, self.stack = self.deferred.popleft()
            self._run_function(function)

    def visit(self, node: ast.AST) -> None:
        _HANDLERS[type(node)](self, node)

    def children(self, node: ast.AST) -> None:
        handlers = _HANDLERS  # :meth:`visit` inline: the walk's most frequent call
        for name in _field_order(type(node)):
            value = getattr(node, name, None)
            if isinstance(value, ast.AST):
                handlers[type(value)](self, value)
            elif isinstance(value, list):
                for item in value:
                    if isinstance(item, ast.AST):
                        handlers[type(item)](self, item)

    def visit_Name(self, node: ast.Name) -> None:
        if isinstance(node.ctx, ast.Load):
            self.load(node.id)
        elif isinstance(node.ctx, ast.Store):
            self.stack[-1].add(node.id)
        else:
            raise Undecided("del")

    def load(self, name: str) -> None:
        innermost = self.stack[-1]
        for scope in reversed(self.stack):
            if scope.is_class and scope is not innermost:
                continue
            if name in scope:
                return
        if name not in _KNOWN:
            raise Undecided(name)

    def visit_Import(self, node: ast.Import) -> None:
        for alias in node.names:
            self.stack[-1].add(alias.asname or alias.name.split(".")[0])

    def visit_ImportFrom(self, node: ast.ImportFrom) -> None:
        for alias in node.names:
            if alias.name == "*":
                raise Undecided("import *")
            self.stack[-1].add(alias.asname or alias.name)

    def visit_AugAssign(self, node: ast.AugAssign) -> None:
        if isinstance(node.target, ast.Name):
            self.load(node.target.id)
        self.visit(node.value)
        self.visit(node.target)

    def visit_AnnAssign(self, node: ast.AnnAssign) -> None:
        self.visit(node.annotation)
        if node.value is not None:
            self.visit(node.value)
            self.visit(node.target)
        elif not isinstance(node.target, ast.Name):  # a bare annotation binds nothing
            self.visit(node.target)

    def visit_ExceptHandler(self, node: ast.ExceptHandler) -> None:
        if node.name is None:
            self.children(node)
            return
        scope = self.stack[-1]
        had = node.name in scope
        scope.add(node.name)
        self.children(node)
        if not had:  # the name is unbound after the handler, as Python does
            scope.discard(node.name)

    def visit_ClassDef(self, node: ast.ClassDef) -> None:
        for part in (*node.decorator_list, *node.bases, *node.keywords):
            self.visit(part)
        self.stack.append(_Scope(is_class=True))
        for statement in node.body:
            self.visit(statement)
        self.stack.pop()
        self.stack[-1].add(node.name)

    def visit_FunctionDef(self, node: ast.FunctionDef | ast.AsyncFunctionDef) -> None:
        for decorator in node.decorator_list:
            self.visit(decorator)
        self._signature(node)
        if node.returns is not None:
            self.visit(node.returns)
        self.stack[-1].add(node.name)
        self.deferred.append((node, list(self.stack)))

    visit_AsyncFunctionDef = visit_FunctionDef

    def visit_Lambda(self, node: ast.Lambda) -> None:
        self._signature(node)
        self.deferred.append((node, list(self.stack)))

    def _signature(self, node: ast.FunctionDef | ast.AsyncFunctionDef | ast.Lambda) -> None:
        arguments = node.args
        for default in (*arguments.defaults, *arguments.kw_defaults):
            if default is not None:
                self.visit(default)
        for argument in _arguments(arguments):
            if argument.annotation is not None:
                self.visit(argument.annotation)

    def _run_function(self, node: ast.AST) -> None:
        assert isinstance(node, _FUNCTIONS)
        scope = _Scope()
        scope.update(argument.arg for argument in _arguments(node.args))
        self.stack.append(scope)
        for statement in node.body if isinstance(node.body, list) else [node.body]:
            self.visit(statement)

    def _comprehension(self, node: ast.AST) -> None:
        self.stack.append(_Scope())
        self.children(node)
        self.stack.pop()

    visit_ListComp = visit_SetComp = visit_DictComp = visit_GeneratorExp = _comprehension


def _undecided(walk: _Walk, node: ast.AST) -> None:
    raise Undecided(type(node).__name__)


def _leaf(walk: _Walk, node: ast.AST) -> None:
    """Nothing to do: a node without child nodes (a constant)."""


class _Handlers(dict[type, Callable[[_Walk, Any], None]]):
    """What :meth:`_Walk.visit` does with a node of each class: the method of :class:`_Walk`
    for it if it has one, else raise :class:`Undecided` or visit the children."""

    def __missing__(self, kind: type) -> Callable[[_Walk, Any], None]:
        handler = getattr(_Walk, "visit_" + kind.__name__, None)
        if handler is None:
            handler = (_undecided if issubclass(kind, _UNDECIDED) else
                       _Walk.children if _field_order(kind) else _leaf)
        self[kind] = handler
        return handler


_HANDLERS = _Handlers()


def _arguments(arguments: ast.arguments) -> list[ast.arg]:
    return [*arguments.posonlyargs, *arguments.args, *arguments.kwonlyargs,
            *(a for a in (arguments.vararg, arguments.kwarg) if a is not None)]


def _strings_read_as_annotations(tree: ast.Module) -> bool:
    """True when pyflakes may read a string of ``tree`` as code: one in an annotation, or one
    inside a subscript or call of something imported from ``typing`` (``Optional['Node']``,
    ``cast('Node', x)``)."""
    names: set[str] = set()
    modules: set[str] = set()
    places: list[ast.AST] = []
    for node in nodes_of_class(tree, ast.Import, ast.ImportFrom, ast.arg, ast.FunctionDef,
                               ast.AsyncFunctionDef, ast.AnnAssign):
        if isinstance(node, ast.Import):
            modules.update(a.asname or a.name for a in node.names if a.name in _TYPING)
        elif isinstance(node, ast.ImportFrom) and node.module in _TYPING:
            names.update(a.asname or a.name for a in node.names)
        elif isinstance(node, ast.arg) and node.annotation is not None:
            places.append(node.annotation)
        elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) and node.returns:
            places.append(node.returns)
        elif isinstance(node, ast.AnnAssign):
            places.append(node.annotation)
    if names or modules:  # else no subscript or call is of a name from typing
        places.extend(nodes_of_class(tree, ast.Subscript, ast.Call))
    return any(isinstance(inner, ast.Constant) and isinstance(inner.value, str)
               for place in places if _typing_member(place, names, modules)
               for inner in descendants(place))


def _typing_member(place: ast.AST, names: set[str], modules: set[str]) -> bool:
    """True for an annotation, or a subscript or call of a name from ``typing``."""
    if not isinstance(place, (ast.Subscript, ast.Call)):
        return True
    used = place.value if isinstance(place, ast.Subscript) else place.func
    return (isinstance(used, ast.Name) and used.id in names) or (
        isinstance(used, ast.Attribute) and isinstance(used.value, ast.Name)
        and used.value.id in modules)


def every_name_defined(tree: ast.Module) -> bool:
    """True when pyflakes would surely report no undefined name in ``tree``."""
    try:
        if _strings_read_as_annotations(tree):
            return False
        _Walk().run(tree)
    except (Undecided, RecursionError):
        return False
    return True
