"""SYN006: Python code that parses but that Python refuses to compile (``f(a=1, a=2)``)."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import enclosing, walk_once
from pkgtool.model.package import Package, is_test_data
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax._problems import set_aside
from pkgtool.rules.syntax_trees import python_files

_FUNCTIONS = (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)
_LOOPS = (ast.For, ast.AsyncFor, ast.While)
_SCOPES = (*_FUNCTIONS, ast.ClassDef, ast.Module)
_OUTSIDE = {ast.Return: "'return' outside function", ast.Yield: "'yield' outside function",
            ast.YieldFrom: "'yield' outside function", ast.Await: "'await' outside function"}
_JUMPS = {ast.Break: "'break' outside loop", ast.Continue: "'continue' not properly in loop"}


def _first_repeated(names: list[str]) -> str | None:
    return next((n for i, n in enumerate(names) if n in names[:i]), None)


def _repeated_keywords(call: ast.Call) -> str | None:
    repeated = _first_repeated([k.arg for k in call.keywords if k.arg is not None])
    return f"keyword argument repeated: {repeated}" if repeated else None


def _duplicate_parameters(function: ast.AST) -> str | None:
    arguments = function.args  # type: ignore[attr-defined]
    repeated = _first_repeated([a.arg for a in (
        *arguments.posonlyargs, *arguments.args, arguments.vararg, *arguments.kwonlyargs,
        arguments.kwarg) if a is not None])
    return f"duplicate argument '{repeated}' in function definition" if repeated else None


def compile_errors(tree: ast.Module) -> Iterator[tuple[ast.AST, str]]:
    """(node, Python's message) for the errors CPython's compiler raises on a parsed tree:
    repeated keywords, duplicate parameters, ``return``/``yield``/``await`` outside a
    function, ``break``/``continue`` outside a loop."""
    walk = walk_once(tree)
    for call in walk.by_class.get(ast.Call, ()):
        problem = _repeated_keywords(call)  # type: ignore[arg-type]
        if problem:
            yield call, problem
    for kind in _FUNCTIONS:
        for function in walk.by_class.get(kind, ()):
            problem = _duplicate_parameters(function)
            if problem:
                yield function, problem
    for kind, problem in _OUTSIDE.items():
        for node in walk.by_class.get(kind, ()):
            if not isinstance(enclosing(node, walk.parents, _SCOPES), _FUNCTIONS):
                yield node, problem
    for kind, problem in _JUMPS.items():
        for node in walk.by_class.get(kind, ()):
            if not isinstance(enclosing(node, walk.parents, (*_LOOPS, *_SCOPES)), _LOOPS):
                yield node, problem


@rule("SYN006", "compile-error", Severity.ERROR, fix="Correct the line so that Python compiles it")
def compile_error(package: Package) -> Iterator[Hit]:
    """Python code parses, but Python refuses to compile it.

    ## What it does
    Reports, in every Python file of the package, the errors CPython raises after parsing,
    when it compiles the file: a keyword argument given twice (`Node(output='screen',
    output='log')`), a parameter named twice (`def cb(self, msg, msg)`), `return`, `yield`
    or `await` outside a function, `break` or `continue` outside a loop. Python files under
    `test/` that pytest does not collect (data a test reads), and files kept aside that
    nothing installs (`backup/old.launch.py`), are left alone, as SYN001 leaves them.

    ## Why is this bad?
    They are `SyntaxError`s like any other, raised when the file is imported: the node, the
    launch file or the test file fails before any of it runs (a test file so broken is an
    error pytest reports for the whole file).

    ## Example
    ```python
    Node(package='demo', executable='talker', output='screen', output='log')
    ```

    ## Use instead
    ```python
    Node(package='demo', executable='talker', output='screen')
    ```
    """
    for path, _, tree in python_files(package):
        if is_test_data(path) or set_aside(package, path):
            continue
        for node, problem in compile_errors(tree):
            yield Hit(Span(path, node.lineno, node.col_offset + 1),  # type: ignore[attr-defined]
                      f"Python refuses to compile this line: SyntaxError: {problem}")
