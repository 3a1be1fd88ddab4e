"""PYC083: a function reads a name it assigns before assigning it (``count += 1`` on a module
variable, ``node = node()``): the name is local to the whole function, the read raises
UnboundLocalError."""

from __future__ import annotations

import ast
import builtins
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import names_bound_by, nodes_of_class, statement_of, subtree
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._own_callees import parameter_names
from pkgtool.rules.registry import rule
from pkgtool.rules.scopes import (ALWAYS, COMPREHENSIONS, NESTED_SCOPES, scope_bindings,
                                  scope_walk)
from pkgtool.rules.syntax_trees import FUNCTIONS, Index, installed_trees

_BUILTINS = frozenset(dir(builtins))
_LOOPS = (ast.For, ast.AsyncFor, ast.While)
_VALUED = (ast.Assign, ast.AugAssign, ast.AnnAssign)
"""Statements that evaluate their value before they bind their targets."""


def _start(node: ast.AST) -> tuple[int, int]:
    return node.lineno, node.col_offset  # type: ignore[attr-defined]


def _binders(function: ast.FunctionDef | ast.AsyncFunctionDef, index: Index
             ) -> tuple[dict[str, list[ast.AST]], list[tuple[ast.AST, str]], set[str]]:
    """The nodes binding each name in the function's own scope; its reads there as (node,
    name): loads of names (also in what nested scopes evaluate at once: a comprehension's
    first iterable, a nested function's decorators and defaults), and the targets of ``x +=
    1`` (which read ``x`` first), not in annotations Python never evaluates nor inside ``try``
    blocks that catch NameError (a probe); and the names a walrus binds anywhere in it
    (left alone: a comprehension's ``:=`` binds in the function)."""
    bindings: dict[str, list[ast.AST]] = {}
    for node in scope_walk(function.body):
        for name in names_bound_by(node):
            bindings.setdefault(name, []).append(node)
    reads: list[tuple[ast.AST, str]] = []
    for node in scope_walk(function.body, skip_protected=True):
        if type(node) in NESTED_SCOPES:
            reads.extend((n, n.id) for n in scope_walk(_evaluated_at_once(node))
                         if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Load))
        elif isinstance(node, ast.Name) and isinstance(node.ctx, ast.Load):
            if not index.in_unevaluated_annotation(node):
                reads.append((node, node.id))
        elif isinstance(node, ast.AugAssign) and isinstance(node.target, ast.Name):
            reads.append((node.target, node.target.id))
    walrus = {n.target.id for n in subtree(function)
              if isinstance(n, ast.NamedExpr) and isinstance(n.target, ast.Name)}
    return bindings, reads, walrus


def _evaluated_at_once(node: ast.AST) -> list[ast.AST]:
    """The parts of a nested scope the enclosing one evaluates where it stands: a
    comprehension's first iterable; a function's or lambda's decorators and defaults; a
    class's decorators, bases and keywords."""
    if isinstance(node, COMPREHENSIONS):
        return [node.generators[0].iter]
    arguments = getattr(node, "args", None)
    defaults = [*arguments.defaults, *(d for d in arguments.kw_defaults if d is not None)] \
        if isinstance(arguments, ast.arguments) else []
    return [*getattr(node, "decorator_list", []), *defaults, *getattr(node, "bases", []),
            *(k.value for k in getattr(node, "keywords", []))]


def _read_first(read: ast.AST, binders: list[ast.AST], index: Index,
                function: ast.AST) -> bool:
    """True when no binding of the name can run before ``read``: every binding is in a later
    statement (or binds the value of ``read``'s own assignment), and no loop around the read
    holds one (a later pass would see it bound)."""
    statement = statement_of(read, index.parents)
    for binder in binders:
        bound = statement_of(binder, index.parents)
        if bound is statement:  # read first only where it is evaluated before the binding
            if not _evaluated_first(read, statement, index):
                return False
        elif _start(bound) <= _start(statement):
            return False
    loop = index.parents.get(id(statement))
    while loop is not None and loop is not function:
        if isinstance(loop, _LOOPS) and any(index.inside(b, {id(loop)}) for b in binders):
            return False
        loop = index.parents.get(id(loop))
    return True


def _evaluated_first(read: ast.AST, statement: ast.AST, index: Index) -> bool:
    """True when ``read`` is in the part of ``statement`` evaluated before it binds anything:
    the value of an assignment (``x += 1`` reads its target first), the iterable of a
    ``for``, the first context manager of a ``with``."""
    if isinstance(statement, ast.AugAssign) and read is statement.target:
        return True
    first = statement.value if isinstance(statement, _VALUED) else \
        statement.iter if isinstance(statement, (ast.For, ast.AsyncFor)) else \
        statement.items[0].context_expr if isinstance(statement, (ast.With, ast.AsyncWith)) \
        else None
    return first is not None and index.inside(read, {id(first)})


def _suspects(tree: ast.Module, index: Index, module_names: set[str]
              ) -> list[ast.FunctionDef | ast.AsyncFunctionDef]:
    """The functions that bind a name the module or Python's builtins define too, and every
    nested function (its enclosing function's names count as well): the others cannot read
    such a name first; found from the tree's one walk, without walking each function."""
    found = {id(f): f for f in index.functions if index.enclosing_function(f) is not None}
    for kind in (ast.Name, *FUNCTIONS, ast.ClassDef, ast.Import, ast.ImportFrom,
                 ast.ExceptHandler, ast.MatchAs, ast.MatchStar, ast.MatchMapping):
        for node in nodes_of_class(tree, kind):
            names = names_bound_by(node)
            if names and any(n in module_names or n in _BUILTINS for n in names):
                function = index.enclosing_function(node, through_lambdas=False)
                if function is not None:
                    found[id(function)] = function
    return list(found.values())


def _outer_names(function: ast.AST, index: Index, module_names: set[str]) -> set[str]:
    """Names bound around ``function``: by the module, or by a function it is nested in."""
    found = set(module_names)
    for outer in index.functions_around(function):
        found.update(name for name, count in scope_bindings(outer).items() if count)
    return found


@rule("PYC083", "local-read-before-assignment", Severity.ERROR,
      fix="Declare `global name` (`nonlocal` in a nested function), or rename the local")
def local_read_before_assignment(package: Package) -> Iterator[Hit]:
    """A function reads a name before assigning it, where the name is also the module's (or
    a builtin): Python makes it local to the whole function, and the read raises
    UnboundLocalError.

    ## What it does
    Reports, in installed modules, the first read of a name in a function (methods and nested
    functions too; not in a class body, which falls back to the module's names) when the
    function assigns the name somewhere (an assignment, `+=`, `for`, `with ... as`, `import`,
    `def`, `except ... as`, a `match` capture, `del`) without declaring it `global` or
    `nonlocal`, no statement before the read binds it, no loop around the read binds it (a
    later pass would see it), and the module, an enclosing function or Python's builtins
    define the name too (what the author meant to read; a name defined nowhere else is
    PYC001's). `count += 1` reads `count` first; `node = node()` calls the local before it
    is bound, and so do `data = [d for d in data]` (a comprehension's first iterable), `for
    key in config:` before `config = ...`, and a nested function's defaults and decorators.
    Reads inside a `try` that catches NameError, in annotations Python never evaluates, and
    names a `:=` binds anywhere in the function are left alone. This is pyflakes' F823,
    without its reports in loops. The help says `nonlocal` for an enclosing function's name.

    ## Why is this bad?
    Python decides at compile time that a name assigned anywhere in a function is local
    everywhere in it: the module's `count` is never read there, and the first read raises
    `UnboundLocalError: cannot access local variable 'count'`, usually inside a timer or
    subscription callback, every time it fires.

    ## Example
    ```python
    count = 0

    def on_tick():
        count += 1
    ```

    ## Use instead
    ```python
    count = 0

    def on_tick():
        global count
        count += 1
    ```
    """
    for module, tree, index in installed_trees(package):
        module_names = {name for name, count in scope_bindings(tree).items() if count}
        for function in _suspects(tree, index, module_names):
            counts = scope_bindings(function)
            parameters = parameter_names(function.args)
            outer = _outer_names(function, index, module_names)
            shadowing = {name for name, count in counts.items() if 0 < count < ALWAYS and
                         (name in outer or name in _BUILTINS)} - parameters
            if not shadowing:
                continue  # most functions: no name of theirs is also the module's
            bindings, reads, walrus = _binders(function, index)
            shadowing -= walrus
            parents = index.parents
            earliest = {name: min(_start(statement_of(b, parents)) for b in bindings[name])
                        for name in shadowing if name in bindings}
            told: set[str] = set()
            for read, name in sorted(reads, key=lambda r: _start(r[0])):
                if name not in earliest or name in told or \
                        _start(statement_of(read, parents)) > earliest[name] or \
                        not _read_first(read, bindings[name], index, function):
                    continue
                told.add(name)
                nested = any(0 < scope_bindings(f)[name] < ALWAYS
                             for f in index.functions_around(function))
                whose = "the enclosing function's" if nested else \
                    "the module's" if name in module_names else "the builtin"
                declare = "nonlocal" if nested else "global"
                yield Hit(Span(module.path, read.lineno, read.col_offset + 1),
                          f"`{name}` is assigned in `{function.name}()`, so it is local to "
                          "the whole function: this read comes before any assignment and "
                          f"raises UnboundLocalError ({whose} `{name}` is not read here)",
                          f"Declare `{declare} {name}` to use {whose}, or give the local "
                          "another name" if whose != "the builtin" else
                          f"Give the local another name than the builtin `{name}`")
