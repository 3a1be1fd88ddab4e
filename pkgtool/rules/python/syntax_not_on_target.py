"""PYC011: syntax that the target distribution's (older) Python cannot parse."""

from __future__ import annotations

import ast
import re
import sys
import warnings
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rosdistro import PYTHON_VERSIONS
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.imports import all_python
from pkgtool.rules.registry import rule
from pkgtool.lazy_regex import lazy_pattern


def _problem(text: str, version: tuple[int, int]) -> SyntaxError | None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            ast.parse(text, feature_version=version)
        except SyntaxError as error:
            return error
        except ValueError:
            return None
    return None


_EXCEPT_STAR = lazy_pattern(r"^[ \t]*except[ \t]*\*", re.MULTILINE)


def _where(path: str, text: str, problem: SyntaxError) -> Span:
    """The error's place; for ``except*`` (reported at the end of its block) the clause."""
    line = problem.lineno or 1
    if "Exception groups" in str(problem.msg):
        starts = [text.count("\n", 0, m.start()) + 1 for m in _EXCEPT_STAR.finditer(text)]
        line = max((s for s in starts if s <= line), default=line)
        return Span(path, line, 1)
    return Span(path, line, problem.offset or 1)


@rule("PYC011", "syntax-not-on-target", Severity.ERROR,
      fix="Write it the way the target distribution's Python understands")
def syntax_not_on_target(package: Package) -> Iterator[Hit]:
    """A Python file uses syntax newer than the target distribution's Python.

    ## What it does
    Parses every Python module and Python launch file (that the Python running pkgtool
    parses) again with the grammar of the target distribution's Python (`ast.parse` with
    `feature_version`; humble 3.10, jazzy 3.12, kilted and rolling 3.12), and reports what
    only a newer Python accepts: `except*` (3.11) or type parameters and `type` aliases (3.12)
    on humble. Only syntax that the running Python knows can be judged: run pkgtool on a
    Python at least as new as the target's for a complete check.

    ## Why is this bad?
    The file is a `SyntaxError` on the robot: the node never starts.

    ## Example
    ```python
    try:
        run()
    except* ValueError:  # humble: Python 3.10
        pass
    ```

    ## Use instead
    ```python
    try:
        run()
    except ValueError:
        pass
    ```
    """
    version = tuple(int(p) for p in PYTHON_VERSIONS[package.context.distro].split("."))
    if version >= sys.version_info[:2]:
        return
    for module in all_python(package):
        text = package.texts.get(module.path)
        problem = None if text is None or module.syntax_error else _problem(text, version)
        if problem is not None:
            yield Hit(_where(module.path, text or "", problem),
                      f"Python {'.'.join(map(str, version))} ({package.context.distro}) cannot "
                      f"parse this: {problem.msg}")
