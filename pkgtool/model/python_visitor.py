"""One ``ast`` pass over a module: its imports (marked guarded) and its top-level names."""

from __future__ import annotations

import ast

from pkgtool.model.modules import Import, PythonModule
from pkgtool.model.span import ParseProblem, Span

_GUARD_EXCEPTIONS = frozenset({"ImportError", "ModuleNotFoundError", "Exception", "BaseException"})


def _catches_import_error(handler: ast.ExceptHandler) -> bool:
    if handler.type is None:
        return True
    types = handler.type.elts if isinstance(handler.type, ast.Tuple) else [handler.type]
    return any(isinstance(t, (ast.Name, ast.Attribute)) and
               (t.id if isinstance(t, ast.Name) else t.attr) in _GUARD_EXCEPTIONS for t in types)


def _is_type_checking(test: ast.expr) -> bool:
    return (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or (
        isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING")


def _mentions_find_spec(test: ast.expr) -> bool:
    return any(isinstance(n, (ast.Attribute, ast.Name)) and
               (n.attr if isinstance(n, ast.Attribute) else n.id) in ("find_spec", "find_loader")
               for n in ast.walk(test))


class _Visitor(ast.NodeVisitor):
    def __init__(self, path: str) -> None:
        self.path = path
        self.imports: list[Import] = []
        self.guard_depth = 0

    def _span(self, node: ast.AST) -> Span:
        return Span(self.path, getattr(node, "lineno", 1), getattr(node, "col_offset", 0) + 1)

    def visit_Import(self, node: ast.Import) -> None:
        for alias in node.names:
            self.imports.append(Import(alias.name, 0, (), self._span(node), self.guard_depth > 0))

    def visit_ImportFrom(self, node: ast.ImportFrom) -> None:
        names = tuple(alias.name for alias in node.names)
        self.imports.append(Import(node.module or "", node.level, names, self._span(node),
                                   self.guard_depth > 0))

    def visit_Try(self, node: ast.Try) -> None:
        guarded = any(_catches_import_error(h) for h in node.handlers)
        self.guard_depth += guarded
        for statement in node.body:
            self.visit(statement)
        self.guard_depth -= guarded
        for part in (*node.handlers, *node.orelse, *node.finalbody):
            self.visit(part)

    visit_TryStar = visit_Try

    def visit_If(self, node: ast.If) -> None:
        guarded = _is_type_checking(node.test) or _mentions_find_spec(node.test)
        self.guard_depth += guarded
        for statement in node.body:
            self.visit(statement)
        self.guard_depth -= guarded
        self.visit(node.test)
        for statement in node.orelse:
            self.visit(statement)


def _top_level_names(tree: ast.Module) -> frozenset[str]:
    names: set[str] = set()
    for node in _flatten(tree.body):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, (ast.Assign, ast.AnnAssign, ast.AugAssign)):
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            for target in targets:
                names.update(n.id for n in ast.walk(target) if isinstance(n, ast.Name))
        elif isinstance(node, (ast.Import, ast.ImportFrom)):
            for alias in node.names:
                if alias.name != "*":
                    names.add((alias.asname or alias.name).split(".")[0])
    return frozenset(names)


def _flatten(body: list[ast.stmt]) -> list[ast.stmt]:
    """Statements at module level, including those inside top-level if/try blocks."""
    result: list[ast.stmt] = []
    for node in body:
        result.append(node)
        if isinstance(node, ast.If):
            result.extend(_flatten(node.body) + _flatten(node.orelse))
        elif isinstance(node, ast.Try):
            result.extend(_flatten(node.body) + _flatten(node.orelse) + _flatten(node.finalbody))
            for handler in node.handlers:
                result.extend(_flatten(handler.body))
    return result


def read_module(path: str, text: str) -> PythonModule:
    """Parse ``text``; a syntax error becomes the module's ``syntax_error``."""
    try:
        tree = ast.parse(text, filename=path)
    except (SyntaxError, ValueError) as error:
        line = getattr(error, "lineno", None) or 1
        col = getattr(error, "offset", None) or 1
        detail = getattr(error, "msg", None) or str(error)
        return PythonModule(path, (), frozenset(), ParseProblem("python-syntax", Span(path, line, col), detail))
    visitor = _Visitor(path)
    visitor.visit(tree)
    return PythonModule(path, tuple(visitor.imports), _top_level_names(tree))
