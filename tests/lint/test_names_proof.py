"""PYC001's quick proof that a module uses no undefined name, held to pyflakes (the oracle).

Whenever the proof says "every name defined", pyflakes must report no undefined name: on every
Python file of the fixtures, the reference packages, pkgtool and its tests, on mutants of each
(a used name renamed to one bound nowhere, statements in reverse order) and on snippets of
the constructs the proof models.
"""

from __future__ import annotations

import ast
import copy
from collections.abc import Iterator
from pathlib import Path

import pytest
from pyflakes.checker import Checker
from pyflakes.messages import UndefinedName

from pkgtool.rules.python._names_proof import every_name_defined

ROOT = Path(__file__).resolve().parents[2]
SOURCES = sorted(path for folder in ("pkgtool", "tests", "reference_packages", "bench")
                 for path in (ROOT / folder).rglob("*.py"))
SNIPPETS = {
    "use before assignment": "print(x)\nx = 1\n",
    "own value": "x = x + 1\n",
    "loop over itself": "for x in x:\n    pass\n",
    "later in a function": "def f():\n    print(y)\n    y = 1\n",
    "module name in a function": "def f():\n    return g()\n\n\ndef g():\n    return 1\n",
    "class variable in a method": "class A:\n    X = 1\n\n    def f(self):\n        return X\n",
    "class variable in the body": "class A:\n    X = 1\n    Y = X + 1\n",
    "class uses its own name": "class A:\n    me = A\n",
    "method uses the class": "class A:\n    def f(self):\n        return A\n",
    "comprehension leaks nothing": "[y for y in range(3)]\nprint(y)\n",
    "comprehension order": "[x for x in range(3) if x]\n",
    "nested comprehension": "[z for y in [[1]] for z in y]\n",
    "comprehension in a class": "class A:\n    X = 1\n    Y = [X for _ in range(2)]\n",
    "except name after": "try:\n    pass\nexcept Exception as e:\n    pass\nprint(e)\n",
    "except name inside": "try:\n    pass\nexcept Exception as e:\n    print(e)\n",
    "except name in a closure": ("try:\n    pass\nexcept Exception as e:\n"
                                 "    def f():\n        return e\n"),
    "except name bound before": ("e = 1\ntry:\n    pass\nexcept Exception as e:\n    pass\n"
                                 "print(e)\n"),
    "augmented unbound": "def f():\n    n += 1\n",
    "augmented bound": "n = 0\nn += 1\n",
    "bare annotation": "x: int\nprint(x)\n",
    "annotated value": "x: int = 1\nprint(x)\n",
    "string annotation": "def f(a: 'Missing'):\n    pass\n",
    "typing string": "from typing import Optional\nX = Optional['Missing']\n",
    "typing cast": "import typing\nx = typing.cast('Missing', 1)\n",
    "default from later": "def f(a=B):\n    pass\n\n\nB = 1\n",
    "decorator from later": "@d\ndef f():\n    pass\n\n\ndef d(g):\n    return g\n",
    "lambda body": "f = lambda a: a + b\nb = 1\n",
    "lambda argument": "f = lambda a: a\n",
    "recursion": "def f(n):\n    return f(n - 1) if n else 0\n",
    "nested later binding": "def f():\n    def g():\n        return h\n    h = 1\n    return g\n",
    "global": "def f():\n    global G\n    G = 1\n\n\ndef g():\n    return G\n",
    "del": "x = 1\ndel x\nprint(x)\n",
    "walrus": "if (n := 3):\n    print(n)\n",
    "star import": "from os.path import *\nprint(join)\n",
    "dunder": "print(__name__, __file__)\n",
    "package dunder": "print(__path__)\n",
    "builtins": "print(len([]), ValueError, __name__)\n",
    "with target": "with open('f') as handle:\n    handle.read()\n",
    "import forms": "import os.path\nimport numpy as np\nfrom a import b as c\nos, np, c\n",
    "f-string": "name = 1\nprint(f'{name} {missing}')\n",
    "keyword default": "def f(*, a=k):\n    pass\n",
    "class keyword": "class A(metaclass=M):\n    pass\n",
    "starred target": "a, *rest = [1, 2]\nprint(rest)\n",
    "try else": "try:\n    import x\nexcept ImportError:\n    x = None\nprint(x)\n",
    "name error guard": "try:\n    unicode\nexcept NameError:\n    unicode = str\n",
}


def _undefined(tree: ast.Module) -> bool:
    return any(isinstance(m, UndefinedName) for m in Checker(tree).messages)


def _sound(tree: ast.Module) -> bool:
    """The proof never claims what pyflakes denies."""
    return not (every_name_defined(tree) and _undefined(tree))


def _trees() -> Iterator[tuple[str, ast.Module]]:
    for path in SOURCES:
        try:
            yield str(path.relative_to(ROOT)), ast.parse(path.read_text(encoding="utf-8"))
        except (SyntaxError, UnicodeDecodeError, ValueError):
            continue


def _renamed(tree: ast.Module) -> Iterator[ast.Module]:
    """The tree with each name it loads (its first load) renamed to one bound nowhere."""
    loaded = {n.id for n in ast.walk(tree) if isinstance(n, ast.Name)
              and isinstance(n.ctx, ast.Load)}
    for name in sorted(loaded)[:12]:
        mutant = copy.deepcopy(tree)
        first = next(n for n in ast.walk(mutant) if isinstance(n, ast.Name)
                     and isinstance(n.ctx, ast.Load) and n.id == name)
        first.id = "bound_nowhere_" + name
        yield mutant


def _reordered(tree: ast.Module) -> Iterator[ast.Module]:
    """The tree with its statements, and each function's, in reverse order."""
    mutant = copy.deepcopy(tree)
    mutant.body.reverse()
    yield mutant
    mutant = copy.deepcopy(tree)
    for node in ast.walk(mutant):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            node.body.reverse()
    yield mutant


@pytest.mark.parametrize("name", sorted(SNIPPETS))
def test_the_proof_agrees_with_pyflakes_on_each_construct(name: str) -> None:
    tree = ast.parse(SNIPPETS[name])
    assert _sound(tree), "proved defined, but pyflakes reports an undefined name"


def test_the_proof_holds_the_simple_cases_it_exists_for() -> None:
    proved = [n for n in SNIPPETS if every_name_defined(ast.parse(SNIPPETS[n]))]
    assert {"module name in a function", "comprehension order", "nested comprehension",
            "except name inside", "annotated value", "lambda argument", "recursion",
            "with target", "import forms", "starred target", "try else",
            "builtins", "nested later binding"} <= set(proved)


def test_the_proof_agrees_with_pyflakes_on_every_file_and_its_mutants() -> None:
    files = proved = mutants = 0
    for path, tree in _trees():
        files += 1
        proved += every_name_defined(tree)
        assert _sound(tree), path
        for mutant in [*_renamed(tree), *_reordered(tree)]:
            mutants += 1
            assert _sound(mutant), path
    assert files > 500 and mutants > 4000
    assert proved > files / 2, "the proof should spare pyflakes most files"
