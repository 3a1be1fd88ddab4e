"""Which functions a function's calls reach, by a rule of the caller's choosing (the class's
methods ``self.x()`` calls, the module functions ``x()`` calls)."""

from __future__ import annotations

import ast
from collections.abc import Callable, Iterable

from pkgtool.model.ast_nodes import subtree
from pkgtool.rules.syntax_trees import FUNCTIONS

Function = ast.FunctionDef | ast.AsyncFunctionDef


def reached(start: Iterable[Function], callee: Callable[[ast.Call, Function], Function | None]
            ) -> list[Function]:
    """The functions the calls of ``start`` reach, and those theirs reach, by ``callee``
    (the function a call of its caller runs, or None), each once, in order found."""
    found: list[Function] = []
    todo = list(start)
    while todo:
        caller = todo.pop()
        for node in subtree(caller):
            target = callee(node, caller) if isinstance(node, ast.Call) else None
            if target is not None and target not in found:
                found.append(target)
                todo.append(target)
    return found


def module_functions_reached(tree: ast.Module, name: str) -> list[Function]:
    """The module function ``name`` (a plain ``def``) and the module functions its calls by
    name reach (``main()`` -> ``parse_options()``), theirs too; empty when it has none."""
    functions = {f.name: f for f in tree.body if isinstance(f, FUNCTIONS)}
    start = functions.get(name)
    if not isinstance(start, ast.FunctionDef):
        return []

    def callee(call: ast.Call, _: Function) -> Function | None:
        return functions.get(call.func.id) if isinstance(call.func, ast.Name) else None
    return [start, *reached([start], callee)]
