"""PYC066: ``@pytest.mark.parametrize`` names an argument its test function does not take."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rosdistro import typo_of
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import index_of
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
    names and functions taking `*args` or `**kwargs` are left alone.

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
    for path, tree in test_trees(package):
        index = index_of(tree)
        for function in index.functions:
            arguments = function.args
            if arguments.vararg or arguments.kwarg:
                continue
            taken = {a.arg for a in (*arguments.posonlyargs, *arguments.args,
                                     *arguments.kwonlyargs)}
            for decorator in function.decorator_list:
                if not isinstance(decorator, ast.Call) or not decorator.args or \
                        index.qualified(decorator.func) != "pytest.mark.parametrize" or \
                        any(k.arg == "indirect" for k in decorator.keywords):
                    continue
                for name in _names(decorator.args[0]) or ():
                    if name not in taken:
                        meant = typo_of(name, taken)
                        hint = f" (did you mean `{meant}`?)" if meant else ""
                        yield Hit(Span(path, decorator.args[0].lineno,
                                       decorator.args[0].col_offset + 1),
                                  f"`parametrize` names `{name}`, which `{function.name}` does "
                                  f"not take{hint}: pytest refuses to collect the test",
                                  f"Write `{meant}`" if meant else None)
