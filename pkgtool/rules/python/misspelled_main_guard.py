"""PYC068: ``if __name__ == '__man__':``, a main guard whose block never runs."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rosdistro import is_typo
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import python_files

_MAIN = "__main__"


def _compared_name(test: ast.expr) -> ast.Constant | None:
    """The string ``__name__`` is compared with for equality in ``test``, if it is one."""
    if not (isinstance(test, ast.Compare) and len(test.ops) == 1 and
            isinstance(test.ops[0], ast.Eq)):
        return None
    sides = (test.left, test.comparators[0])
    if not any(isinstance(s, ast.Name) and s.id == "__name__" for s in sides):
        return None
    text = next((s for s in sides if isinstance(s, ast.Constant)), None)
    return text if text is not None and isinstance(text.value, str) else None


def _misspelt(value: str) -> bool:
    """True for a misspelling of ``'__main__'``: its underscores aside, ``main`` or a typo
    away from it (``'main'``, ``'_main_'``, ``'__man__'``, ``'__mian__'``)."""
    core = value.strip("_")
    return value != _MAIN and len(core) >= 3 and (core == "main" or is_typo(core, "main"))


@rule("PYC068", "misspelled-main-guard", Severity.WARNING,
      fix="Write `if __name__ == '__main__':`")
def misspelled_main_guard(package: Package) -> Iterator[Hit]:
    """A module's `if __name__ == ...:` compares with a misspelling of `'__main__'`.

    ## What it does
    Reports the string a module's top-level `if` compares `__name__` with when it is not
    `'__main__'` but, underscores aside, `main` or a typo away from it (`'main'`, `'_main_'`,
    `'__man__'`, `'__mian__'`), in every Python file of the package.

    ## Why is this bad?
    `__name__` is never that string, so the block never runs: `python3 my_node.py` starts
    nothing and says nothing. (`ros2 run` calls the console script's function directly and
    still works, which is why the mistake survives.)

    ## Example
    ```python
    if __name__ == '__man__':
        main()
    ```

    ## Use instead
    ```python
    if __name__ == '__main__':
        main()
    ```
    """
    for path, _, tree in python_files(package, ("__name__",)):
        for statement in tree.body:
            text = _compared_name(statement.test) if isinstance(statement, ast.If) else None
            if text is not None and _misspelt(text.value):
                yield Hit(Span(path, text.lineno, text.col_offset + 1),
                          f"`__name__` is never `{text.value!r}`: the block under this `if` "
                          "never runs (`python3` on the file starts nothing)",
                          "Write `'__main__'`")
