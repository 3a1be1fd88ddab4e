"""One ``ast`` pass over a module: its imports (marked guarded) and its top-level names."""

from __future__ import annotations

import ast
import functools
from collections.abc import Callable

from pkgtool.model.ast_nodes import (TRIES, block_statements, descendants, enclosing,
                                     handler_stops, statement_of, subtree, walk_once)
from pkgtool.model.memo import forget_tree_facts
from pkgtool.model.modules import Import, PythonModule
from pkgtool.model.span import ParseProblem, Span
from pkgtool.model.static_branches import mentions_module_name, module_constants, truth

_GUARD_EXCEPTIONS = frozenset({"ImportError", "ModuleNotFoundError", "Exception", "BaseException"})


def catches_import_error(handler: ast.ExceptHandler) -> bool:
    """True for a handler that catches ImportError (bare, or naming it, ModuleNotFoundError,
    Exception or BaseException)."""
    if handler.type is None:
        return True
    types = handler.type.elts if isinstance(handler.type, ast.Tuple) else [handler.type]
    return _names_import_error(types)


def _names_import_error(types: list[ast.expr]) -> bool:
    """True when one of the exception classes ``types`` catches ImportError."""
    return any(isinstance(t, (ast.Name, ast.Attribute)) and
               (t.id if isinstance(t, ast.Name) else t.attr) in _GUARD_EXCEPTIONS for t in types)


def _suppresses_import_error(node: ast.With | ast.AsyncWith) -> bool:
    """True for ``with contextlib.suppress(ImportError):`` (or a broader class)."""
    return any(isinstance(call := item.context_expr, ast.Call) and
               isinstance(call.func, (ast.Name, ast.Attribute)) and
               (call.func.id if isinstance(call.func, ast.Name) else call.func.attr) == "suppress"
               and _names_import_error(call.args) for item in node.items)


def _is_type_checking(test: ast.expr) -> bool:
    return (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or (
        isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING")


def _mentions_find_spec(test: ast.expr) -> bool:
    return any(isinstance(n, (ast.Attribute, ast.Name)) and
               (n.attr if isinstance(n, ast.Attribute) else n.id) in ("find_spec", "find_loader")
               for n in descendants(test))


def _is_find_spec_exit(node: ast.AST) -> bool:
    """True for a guard clause on a module's presence: ``if find_spec("x") is None: raise``."""
    return isinstance(node, ast.If) and bool(node.body) and \
        isinstance(node.body[-1], (ast.Raise, ast.Return)) and _mentions_find_spec(node.test)


_INSTALLERS = frozenset({"check_requirements", "check_requirement", "install_requirements",
                         "pip_install"})
"""Functions that pip-install a missing requirement on demand (YOLOv5's and Ultralytics'
``check_requirements('onnxruntime')`` before ``import onnxruntime``)."""


def _installs_on_demand(node: ast.AST) -> bool:
    """True for a statement that is a call of an on-demand installer (:data:`_INSTALLERS`)."""
    call = node.value if isinstance(node, ast.Expr) else None
    func = call.func if isinstance(call, ast.Call) else None
    return (func.id if isinstance(func, ast.Name) else func.attr if
            isinstance(func, ast.Attribute) else "") in _INSTALLERS


def _block(statements: list[ast.AST], guarded: bool) -> list[tuple[ast.AST, bool]]:
    """``statements`` each with whether its imports are guarded: those after a
    :func:`_is_find_spec_exit` guard clause are, like those inside such an ``if``, and so
    are those after an on-demand install (:func:`_installs_on_demand`)."""
    parts = []
    for statement in statements:
        parts.append((statement, guarded))
        guarded = guarded or _is_find_spec_exit(statement) or _installs_on_demand(statement)
    return parts


def _import_probes(tree: ast.Module) -> frozenset[str]:
    """The module-level functions that try an import and catch its ImportError without
    stopping: availability probes (``def is_jupyter(): try: import IPython ... except
    ImportError: return False``)."""
    return frozenset(
        function.name for function in tree.body
        if isinstance(function, (ast.FunctionDef, ast.AsyncFunctionDef))
        and any(isinstance(node, TRIES)
                and any(isinstance(s, (ast.Import, ast.ImportFrom)) for s in node.body)
                and any(catches_import_error(h) and not handler_stops(h) for h in node.handlers)
                for node in subtree(function)))


def _calls_probe(test: ast.expr, probes: Callable[[], frozenset[str]]) -> bool:
    """True when ``test`` calls one of the availability ``probes`` (``if is_jupyter():``)."""
    called = {n.func.id for n in descendants(test)
              if isinstance(n, ast.Call) and isinstance(n.func, ast.Name)}
    return bool(called) and not called.isdisjoint(probes())


def _guarded_parts(node: ast.AST, constants: dict[str, bool],
                   probes: Callable[[], frozenset[str]], at_top: bool
                   ) -> list[tuple[ast.AST, bool]]:
    """The statements directly inside ``node``, each with whether ``node`` guards its imports
    (they are guarded too when a block around ``node`` guards it). A ``try`` at the top of
    the module (``at_top``) whose handler stops the program guards nothing: the module cannot
    be imported without what it imports (in a function or a branch, it is a feature's)."""
    if isinstance(node, TRIES):
        return (_block(node.body, any(catches_import_error(h) and
                                      not (at_top and handler_stops(h)) for h in node.handlers))
                + [(h, catches_import_error(h)) for h in node.handlers]
                + _block(node.orelse, False) + _block(node.finalbody, False))
    if isinstance(node, ast.If):
        value = truth(node.test, constants)
        either = _mentions_find_spec(node.test) or mentions_module_name(node.test)
        inner = either or _is_type_checking(node.test) or value is False or \
            _calls_probe(node.test, probes)
        return _block(node.body, inner) + _block(node.orelse, either or value is True)
    if isinstance(node, (ast.With, ast.AsyncWith)):
        return _block(node.body, _suppresses_import_error(node))
    return [part for field in _BLOCK_FIELDS for part in _block(getattr(node, field, []), False)]


_BLOCK_FIELDS = ("body", "orelse", "finalbody", "handlers", "cases")
"""The fields of compound statements that hold statements (where imports can stand)."""


def _imports(path: str, tree: ast.Module) -> list[Import]:
    """Every import of the module in source order."""
    walk = walk_once(tree)
    statements = [*walk.by_class.get(ast.Import, ()), *walk.by_class.get(ast.ImportFrom, ())]
    if not statements:
        return []
    guarded = _guard_finder(tree, walk.parents)
    found: list[Import] = []
    for node in statements:
        span = Span(path, node.lineno, node.col_offset + 1)  # type: ignore[attr-defined]
        flag = guarded(node)
        if isinstance(node, ast.Import):
            found.extend(Import(a.name, 0, (), span, flag) for a in node.names)
        elif isinstance(node, ast.ImportFrom):
            names = tuple(alias.name for alias in node.names)
            found.append(Import(node.module or "", node.level, names, span, flag))
    return sorted(found, key=lambda i: (i.span.line, i.span.col))


def _guard_finder(tree: ast.Module, parents: dict[int, ast.AST]) -> Callable[[ast.AST], bool]:
    """A function telling whether a statement of ``tree`` is guarded: whether some block
    holding it (the statement's own, or one around it) guards what it holds.

    Each statement holding an import is looked at once (:func:`_guarded_parts`), the others
    not at all.
    """
    constants = module_constants(tree)
    probes = functools.cache(lambda: _import_probes(tree))
    blocks: dict[int, dict[int, bool]] = {}

    def in_blocks(node: ast.AST) -> bool:
        while node is not tree:
            parent = parents[id(node)]
            flags = blocks.get(id(parent))
            if flags is None:
                at_top = parents.get(id(parent)) is tree
                parts = _guarded_parts(parent, constants, probes, at_top)
                flags = blocks[id(parent)] = {id(part): flag for part, flag in parts}
            if flags[id(node)]:
                return True
            node = parent
        return False

    def guarded(node: ast.AST) -> bool:
        if in_blocks(node):
            return True
        uses = _uses_of_function_around(node, tree, parents)
        return bool(uses) and all(isinstance(use, ast.Call) and
                                  _in_try_with_fallback(statement_of(use, parents), parents)
                                  for use in uses)

    return guarded


def _in_try_with_fallback(node: ast.AST, parents: dict[int, ast.AST]) -> bool:
    """True when ``node`` stands in the body of a ``try`` whose handler catches ImportError
    (or a broader class) and goes on (neither re-raises at its end nor exits)."""
    child, parent = node, parents.get(id(node))
    while parent is not None:
        if isinstance(parent, TRIES) and any(child is part for part in parent.body) and any(
                catches_import_error(h) and not handler_stops(h) for h in parent.handlers):
            return True
        child, parent = parent, parents.get(id(parent))
    return False


def _uses_of_function_around(node: ast.AST, tree: ast.Module, parents: dict[int, ast.AST]
                             ) -> list[ast.AST]:
    """Where the module uses the module-level function ``node`` is in (a call of it, or any
    other use of its name; not ``main``, which a console script calls), or the class whose
    ``__init__`` it is in; none for code elsewhere: an import there runs only when a use does
    (``RPiBackend()`` called under ``try/except Exception`` with a fallback makes the
    backend's own import optional)."""
    function = enclosing(node, parents, (ast.FunctionDef, ast.AsyncFunctionDef))
    if not isinstance(function, (ast.FunctionDef, ast.AsyncFunctionDef)):
        return []
    owner = parents.get(id(function))
    if owner is tree and function.name != "main":  # main: a console script's, called elsewhere
        name = function.name
    elif isinstance(owner, ast.ClassDef) and function.name == "__init__" and \
            parents.get(id(owner)) is tree:
        name = owner.name
    else:
        return []
    uses: list[ast.AST] = []
    for use in walk_once(tree).by_class.get(ast.Name, ()):
        if use.id == name and isinstance(use.ctx, ast.Load):  # type: ignore[attr-defined]
            call = parents.get(id(use))
            uses.append(call if isinstance(call, ast.Call) and call.func is use else use)
    return uses


def _top_level_names(tree: ast.Module) -> frozenset[str]:
    names: set[str] = set()
    for node in block_statements(tree.body, (ast.If, ast.Try)):  # at module level
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, (ast.Assign, ast.AnnAssign, ast.AugAssign)):
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            for target in targets:
                names.update(n.id for n in descendants(target) if isinstance(n, ast.Name))
        elif isinstance(node, (ast.Import, ast.ImportFrom)):
            for alias in node.names:
                if alias.name != "*":
                    names.add((alias.asname or alias.name).split(".")[0])
    return frozenset(names)


@functools.lru_cache(maxsize=8192)
def parse_tree(path: str, text: str) -> ast.Module | ParseProblem:
    """``ast.parse`` that turns every parser failure into a ``python-syntax`` problem.

    Cached: the model and the rules that walk syntax trees share one parse per file. Callers
    must treat the tree as read-only.
    """
    try:
        return ast.parse(text, filename=path)
    except (SyntaxError, ValueError) as error:
        line = getattr(error, "lineno", None) or 1
        col = getattr(error, "offset", None) or 1
        detail = getattr(error, "msg", None) or str(error)
        return ParseProblem("python-syntax", Span(path, line, col), detail)
    except (RecursionError, MemoryError):
        return ParseProblem("python-syntax", Span(path, 1, 1),
                            "the code is nested too deeply to parse")


def forget_trees() -> None:
    """Drop the trees :func:`parse_tree` keeps: call it when done with a package, so the
    next packages' work does not carry (and the garbage collector does not walk) them, nor
    what the rules worked out from them (:func:`~pkgtool.model.memo.per_tree`)."""
    parse_tree.cache_clear()
    forget_tree_facts()


def module_from_tree(path: str, tree: ast.Module) -> PythonModule:
    """The imports and top-level names of an already parsed module."""
    return PythonModule(path, tuple(_imports(path, tree)), _top_level_names(tree))


def read_module(path: str, text: str) -> PythonModule:
    """Parse ``text``; a syntax error becomes the module's ``syntax_error``, and the imports
    and names are those of the top-level statements before it (:func:`_statements_before`)."""
    tree = parse_tree(path, text)
    if isinstance(tree, ParseProblem):
        before = _statements_before(text, tree.span.line)
        if before is None:
            return PythonModule(path, (), frozenset(), tree)
        return PythonModule(path, tuple(_imports(path, before)), _top_level_names(before), tree)
    return module_from_tree(path, tree)


_TRIES = 4
"""How many top-level statement starts above a syntax error :func:`_statements_before` tries
after the lines above it: the file's imports are above the function or class holding it."""


def _statements_before(text: str, line: int) -> ast.Module | None:
    """The syntax tree of the top-level statements that end before ``line``, where a syntax
    error is (a later line of a file cut short there parses alone): the file's lines above
    the error, else cut at the start of the statement holding it, or of one above that when
    it does not parse (a string's lines at column 0); None when none of :data:`_TRIES` cuts parses
    or there is nothing above it. Never run, only parsed."""
    lines = text.splitlines(keepends=True)[:max(line - 1, 0)]
    starts = [number for number, source in enumerate(lines)
              if source[:1] not in ("", " ", "\t", "\n", "\r", "#", ")", "]", "}")]
    for cut in (len(lines), *reversed(starts[-_TRIES:])):
        try:
            tree = ast.parse("".join(lines[:cut]))
        except (SyntaxError, ValueError, RecursionError, MemoryError):
            continue
        return tree if tree.body else None
    return None
