"""SYN006 against CPython's own compiler: the errors it finds on a parsed tree are exactly
those ``compile()`` raises, with the same message."""

from __future__ import annotations

import ast

import pytest

from pkgtool.rules.syntax.compile_error import compile_errors

SOURCES = [
    "f(a=1, a=2)", "f(a=1, b=2, **{'a': 3})", "def f(a, a): pass", "def f(a, *, b, b=1): pass",
    "lambda a, a: 1", "def f(*a, **a): pass", "return 1", "class A:\n    return 1",
    "def f():\n    return 1", "yield 1", "def f():\n    yield 1", "await x",
    "async def f():\n    await x", "break", "for x in y:\n    break",
    "while x:\n    continue", "for x in y:\n    def g():\n        break",
    "while x:\n    class A:\n        continue", "def f():\n    lambda: (yield)",
    "for x in y:\n    pass\nelse:\n    pass", "f(x for x in y)",
]


@pytest.mark.parametrize("source", SOURCES)
def test_compile_errors_are_the_compilers(source: str) -> None:
    tree = ast.parse(source)
    try:
        compile(tree, "<test>", "exec", dont_inherit=True)
        expected = []
    except SyntaxError as error:
        expected = [error.msg]
    assert [problem for _, problem in compile_errors(tree)] == expected
