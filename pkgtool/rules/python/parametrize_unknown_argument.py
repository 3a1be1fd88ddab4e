"""PYC066: ``@pytest.mark.parametrize`` names an argument its test function does not take."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rosdistro import typo_of
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule
from pkgtool.records import record
from pkgtool.rules.syntax_trees import Index, index_of
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
    fixtures = _fixtures(trees)
    for path, tree in trees:
        index = index_of(tree)
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
                    reached = _closure(taken | _marked(function, index), fixtures) \
                        if reached is None else reached
                    if name not in reached:
                        meant = typo_of(name, taken)
                        hint = f" (did you mean `{meant}`?)" if meant else ""
                        yield Hit(Span(path, decorator.args[0].lineno,
                                       decorator.args[0].col_offset + 1),
                                  f"`parametrize` names `{name}`, which `{function.name}` does "
                                  f"not take{hint}: pytest refuses to collect the test",
                                  f"Write `{meant}`" if meant else None)


@record
class _Fixtures:
    """The fixtures the package's test files define: the names each requests, by fixture
    name, and those used by every test (``autouse=True``)."""

    requests: dict[str, frozenset[str]]
    autouse: frozenset[str]


def _fixtures(trees: list[tuple[str, ast.Module]]) -> _Fixtures:
    requests: dict[str, set[str]] = {}
    autouse: set[str] = set()
    for _, tree in trees:
        index = index_of(tree)
        for function in index.functions:
            for decorator in function.decorator_list:
                called = decorator.func if isinstance(decorator, ast.Call) else decorator
                if index.qualified(called) not in ("pytest.fixture", "pytest.yield_fixture"):
                    continue
                keywords = decorator.keywords if isinstance(decorator, ast.Call) else []
                renamed = next((k.value.value for k in keywords if k.arg == "name" and
                                isinstance(k.value, ast.Constant)), None)
                name = renamed if isinstance(renamed, str) else function.name
                requests.setdefault(name, set()).update(
                    a.arg for a in (*function.args.posonlyargs, *function.args.args,
                                    *function.args.kwonlyargs))
                requests[name].update(_used_fixtures(function, index))
                if any(k.arg == "autouse" and isinstance(k.value, ast.Constant) and
                       k.value.value is True for k in keywords):
                    autouse.add(name)
    return _Fixtures({k: frozenset(v) for k, v in requests.items()}, frozenset(autouse))


def _used_fixtures(node: ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef,
                   index: Index) -> set[str]:
    """The names ``@pytest.mark.usefixtures('a', 'b')`` gives ``node``."""
    return {argument.value for decorator in node.decorator_list
            if isinstance(decorator, ast.Call) and
            index.qualified(decorator.func) == "pytest.mark.usefixtures"
            for argument in decorator.args
            if isinstance(argument, ast.Constant) and isinstance(argument.value, str)}


def _marked(function: ast.FunctionDef | ast.AsyncFunctionDef, index: Index) -> set[str]:
    """The fixtures ``usefixtures`` marks give the test and its class."""
    cls = index.enclosing_class(function)
    return _used_fixtures(function, index) | (_used_fixtures(cls, index) if cls else set())


def _closure(taken: set[str], fixtures: _Fixtures) -> set[str]:
    """Every name the test's fixture closure holds, which pytest lets ``parametrize`` set
    (overriding a fixture a requested fixture depends on): its parameters, the autouse
    fixtures and those ``usefixtures`` names, and what each requested fixture requests in
    turn."""
    found: set[str] = set()
    todo = [*taken, *fixtures.autouse]
    while todo:
        name = todo.pop()
        if name not in found:
            found.add(name)
            todo.extend(fixtures.requests.get(name, ()))
    return found
