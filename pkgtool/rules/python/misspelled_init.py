"""PYC062: a class's constructor misspelt (``__int__``, ``_init_``), so Python never runs it."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rosdistro import is_typo
from pkgtool.model.ast_nodes import is_super_init, nodes_of_class
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import FUNCTIONS, installed_trees

_REAL = frozenset({"__int__"})
"""The special method Python does have a typo away from ``__init__`` (conversion to int)."""


def _init_like(name: str) -> bool:
    """True for ``__init__`` misspelt: its letters a typo from ``init`` (``__int__``,
    ``__inti__``, ``_init_``, ``__init``), and not ``__init__`` itself."""
    return name != "__init__" and is_typo(name.strip("_"), "init")


def _runs_base_init(method: ast.FunctionDef | ast.AsyncFunctionDef) -> bool:
    """True when the method calls ``super().__init__(...)`` (or ``super(C, self).__init__``)."""
    return any(is_super_init(call) for call in nodes_of_class(method, ast.Call))


@rule("PYC062", "misspelled-init", Severity.ERROR, fix="Name the method `__init__`")
def misspelled_init(package: Package) -> Iterator[Hit]:
    """A class's constructor is misspelt, so Python never runs it.

    ## What it does
    In installed modules, reports a method of a class that defines no `__init__` when its name
    is `__init__` misspelt (its letters a typo from `init`: `__int__`, `__inti__`, `_init_`,
    `__init`, `init__`) and either it calls `super().__init__(...)`, as only a constructor
    does, or it is written like a special method (`_init_`, `__inti__`) that Python does not
    have, or `__int__` taking parameters besides `self` (`int()` passes none). Real special
    methods (`__int__(self)` converting to a number, `__iter__`, `__new__`) that do not call
    `super().__init__` and methods the module calls by name are left alone.

    ## Why is this bad?
    Python calls `__init__` when it makes an object; a method of another name only runs when
    called. The class uses its base's constructor instead: a node subclass then fails at once
    (`Node.__init__() missing 1 required positional argument: 'node_name'`), or makes a node
    without its publishers, timers and attributes, so the first callback fails.

    ## Example
    ```python
    class Talker(Node):
        def __int__(self):
            super().__init__('talker')
    ```

    ## Use instead
    ```python
    class Talker(Node):
        def __init__(self):
            super().__init__('talker')
    ```
    """
    for module, tree, index in installed_trees(package):
        called = {node.attr for node in index.attributes}
        for cls in index.classes:
            methods = [s for s in cls.body if isinstance(s, FUNCTIONS)]
            if any(m.name == "__init__" for m in methods):
                continue
            for method in methods:
                if not _init_like(method.name) or method.name in called:
                    continue
                special = method.name.startswith("_") and method.name.endswith("_")
                if _runs_base_init(method) or special and (
                        method.name not in _REAL or _takes_arguments(method)):
                    yield Hit(Span(module.path, method.lineno, method.col_offset + 1),
                              f"`{cls.name}` defines `{method.name}`, not `__init__`: Python "
                              f"never calls it when a `{cls.name}` is made, and the base "
                              "class's constructor runs instead", "Write `__init__`")


def _takes_arguments(method: ast.FunctionDef | ast.AsyncFunctionDef) -> bool:
    """True for a method with parameters besides its receiver: never the special method
    ``__int__``, which ``int()`` calls with none (``def __int__(self, rate=10)`` is a
    constructor misspelt)."""
    arguments = method.args
    return len([*arguments.posonlyargs, *arguments.args]) > 1 or bool(arguments.kwonlyargs) \
        or arguments.vararg is not None or arguments.kwarg is not None
