"""PYC066: ``@pytest.mark.parametrize`` names an argument its test function does not take."""

from __future__ import annotations

import ast
import posixpath
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rosdistro import typo_of
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.pytest_fixtures import fixture_name, is_fixture
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import FUNCTIONS, Index, index_of
from pkgtool.rules.test_modules import test_trees


def _names(argnames: ast.expr) -> list[str] | None:
    """The argument names a parametrize call gives: ``'a, b'`` or ``('a', 'b')``; None when
    they are computed."""
    if isinstance(argnames, ast.Constant) and isinstance(argnames.value, str):
        return [n.strip() for n in argnames.value.split(",") if n.strip()]
    if isinstance(argnames, (ast.Tuple, ast.List)) and all(
            isinstance(e, ast.Constant) and isinstance(e.value, str) for e in argnames.elts):
        return [e.value for e in argnames.elts]  # type: ignore[attr-defined]
    return None


@rule("PYC066", "parametrize-unknown-argument", Severity.ERROR,
      fix="Name the test function's parameters in `parametrize` (check the spelling)")
def parametrize_unknown_argument(package: Package) -> Iterator[Hit]:
    """`@pytest.mark.parametrize` names an argument the test function does not take.

    ## What it does
    In the package's test modules, reports a name in the first argument of
    `@pytest.mark.parametrize(...)` (`'speed'`, `'speed, expected'` or `('speed',
    'expected')`) that the decorated function has no parameter for, with the parameter a typo
    away when there is one. Calls with `indirect=` (the names are fixtures then), computed
    names and functions taking `*args` or `**kwargs` are left alone, and so is a name in the
    test's fixture closure (a fixture of the package's test files or `conftest.py` that the
    test requests, directly, through other fixtures, `usefixtures` or `autouse`, depends
    on it: parametrizing it overrides that fixture, as pytest documents).

    ## Why is this bad?
    pytest refuses the test at collection ("In test_speed: function uses no argument
    'sped'"): the whole module errors, and none of its tests runs, while a misspelt parameter
    of the function becomes a fixture pytest cannot find.

    ## Example
    ```python
    @pytest.mark.parametrize('sped', [0.1, 1.0])
    def test_speed(speed):
        ...
    ```

    ## Use instead
    ```python
    @pytest.mark.parametrize('speed', [0.1, 1.0])
    def test_speed(speed):
        ...
    ```
    """
    trees = list(test_trees(package))
    shared = _Fixtures()
    for path, tree in trees:
        if posixpath.basename(path) == "conftest.py":
            _collect(shared, tree, index_of(tree), None)
    for path, tree in trees:
        index = index_of(tree)
        here = _Fixtures(dict(shared.requests), set(shared.autouse))
        _collect(here, tree, index, None)  # module fixtures override the conftest's
        for function in index.functions:
            arguments = function.args
            if arguments.vararg or arguments.kwarg:
                continue
            taken = {a.arg for a in (*arguments.posonlyargs, *arguments.args,
                                     *arguments.kwonlyargs)}
            reached: set[str] | None = None
            for decorator in function.decorator_list:
                if not isinstance(decorator, ast.Call) or not decorator.args or \
                        index.qualified(decorator.func) != "pytest.mark.parametrize" or \
                        any(k.arg == "indirect" for k in decorator.keywords):
                    continue
                for name in _names(decorator.args[0]) or ():
                    if name in taken:
                        continue
                    reached = _closure(taken, function, tree, index, here) \
                        if reached is None else reached
                    if name not in reached:
                        meant = typo_of(name, taken)
                        hint = f" (did you mean `{meant}`?)" if meant else ""
                        yield Hit(Span(path, decorator.args[0].lineno,
                                       decorator.args[0].col_offset + 1),
                                  f"`parametrize` names `{name}`, which `{function.name}` does "
                                  f"not take{hint}: pytest refuses to collect the test",
                                  f"Write `{meant}`" if meant else None)


class _Fixtures:
    """Fixtures a test sees: the names each requests, by fixture name, and those used by
    every test of the scope (``autouse=True``)."""

    def __init__(self, requests: dict[str, set[str]] | None = None,
                 autouse: set[str] | None = None) -> None:
        self.requests: dict[str, set[str]] = requests if requests is not None else {}
        self.autouse: set[str] = autouse if autouse is not None else set()


def _collect(into: _Fixtures, tree: ast.Module, index: Index, cls: ast.ClassDef | None) -> None:
    """Add the fixtures defined directly in ``cls`` (or at the top of ``tree``: ``None``) to
    ``into``, each replacing one of its name."""
    body = cls.body if cls is not None else tree.body
    for function in body:
        if not isinstance(function, FUNCTIONS) or not is_fixture(function, index):
            continue
        name = fixture_name(function)
        arguments = function.args
        into.requests[name] = {a.arg for a in (*arguments.posonlyargs, *arguments.args,
                                               *arguments.kwonlyargs)} | \
            _used_fixtures(function.decorator_list, index)
        if any(k.arg == "autouse" and isinstance(k.value, ast.Constant) and
               k.value.value is True for d in function.decorator_list
               if isinstance(d, ast.Call) for k in d.keywords):
            into.autouse.add(name)


def _used_fixtures(marks: list[ast.expr], index: Index) -> set[str]:
    """The names ``pytest.mark.usefixtures('a', 'b')`` marks among ``marks`` give."""
    return {argument.value for mark in marks
            if isinstance(mark, ast.Call) and
            index.qualified(mark.func) == "pytest.mark.usefixtures"
            for argument in mark.args
            if isinstance(argument, ast.Constant) and isinstance(argument.value, str)}


def _pytestmark(body: list[ast.stmt]) -> list[ast.expr]:
    """The marks a ``pytestmark = ...`` assignment of ``body`` gives (one or a list)."""
    marks: list[ast.expr] = []
    for statement in body:
        if isinstance(statement, ast.Assign) and any(
                isinstance(t, ast.Name) and t.id == "pytestmark" for t in statement.targets):
            value = statement.value
            marks.extend(value.elts if isinstance(value, (ast.List, ast.Tuple)) else [value])
    return marks


def _closure(taken: set[str], function: ast.FunctionDef | ast.AsyncFunctionDef,
             tree: ast.Module, index: Index, fixtures: _Fixtures) -> set[str]:
    """Every name the test's fixture closure holds, which pytest lets ``parametrize`` set
    (overriding a fixture a requested fixture depends on): its parameters, the autouse
    fixtures of its module and class, those its `usefixtures` marks (on it, its class, or a
    `pytestmark`) name, and what each requested fixture requests in turn."""
    cls = index.enclosing_class(function)
    if cls is not None:
        fixtures = _Fixtures(dict(fixtures.requests), set(fixtures.autouse))
        _collect(fixtures, tree, index, cls)
    marks = [*function.decorator_list, *_pytestmark(tree.body),
             *((*cls.decorator_list, *_pytestmark(cls.body)) if cls is not None else ())]
    found: set[str] = set()
    todo = [*taken, *fixtures.autouse, *_used_fixtures(marks, index)]
    while todo:
        name = todo.pop()
        if name not in found:
            found.add(name)
            todo.extend(fixtures.requests.get(name, ()))
    return found
