"""PYC079: a standard library call given a keyword it does not take (``sorted(reversed=True)``)."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rosdistro import typo_of
from pkgtool.knowledge.stdlib_signatures import keywords_of
from pkgtool.model.ast_nodes import TRIES
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, index_of, python_files


@rule("PYC079", "stdlib-unexpected-keyword", Severity.ERROR,
      fix="Use a keyword the function takes (see the message)")
def stdlib_unexpected_keyword(package: Package) -> Iterator[Hit]:
    """A standard library function or builtin is called with a keyword it does not take.

    ## What it does
    In every Python file of the package, reports keyword arguments that a common standard
    library call takes on no Python from 3.10 to 3.13 (Humble to Rolling), with the keyword a
    typo away when there is one: `sorted(items, reversed=True)`, `print(text, flsh=True)`,
    `@dataclass(froen=True)`, `subprocess.run(cmd, chek=True)`, `timedelta(second=5)`,
    `threading.Thread(traget=spin)`, `os.makedirs(path, exists_ok=True)`. The calls are those
    of a generated table (builtins such as `print`, `open`, `sorted`, `max`; `dataclasses`,
    `subprocess`, `threading`, `shutil`, `os`, `re`, `random`, `tempfile`, `datetime.timedelta`
    and others), called through an import or, for a builtin, by a name the module never
    binds. Calls passing `**kwargs`, and calls inside a `try` that catches `TypeError` (code
    probing which Python it runs on), are left alone.

    ## Why is this bad?
    The call raises `TypeError: ... got an unexpected keyword argument` when it runs: at
    import for a decorator such as `@dataclass(...)`, often inside a callback for the others,
    where the executor logs it and the node stops doing its job.

    ## Example
    ```python
    ranked = sorted(scores, reversed=True)
    subprocess.run(['ros2', 'topic', 'list'], chek=True)
    ```

    ## Use instead
    ```python
    ranked = sorted(scores, reverse=True)
    subprocess.run(['ros2', 'topic', 'list'], check=True)
    ```
    """
    for path, _, tree in python_files(package):
        index = index_of(tree)
        for call in index.calls:
            if not call.keywords or any(k.arg is None for k in call.keywords):
                continue
            named = _called(call.func, index)
            keywords = keywords_of(named) if named else None
            if named is None or keywords is None:
                continue
            wrong = [k for k in call.keywords if k.arg not in keywords]
            if not wrong or _probing(call, index):
                continue
            shown = f"`{ast.unparse(call.func)}()`"
            for keyword in wrong:
                meant = typo_of(str(keyword.arg), keywords)
                hint = f" (did you mean `{meant}`?)" if meant else ""
                listed = ", ".join(f"`{k}`" for k in sorted(keywords)) or "none"
                yield Hit(Span(path, keyword.lineno, keyword.col_offset + 1),
                          f"{shown} has no `{keyword.arg}` argument on Python 3.10-3.13{hint}: "
                          "the call raises TypeError",
                          f"Write `{meant}=`" if meant else f"Use one of its keywords: {listed}")


def _called(func: ast.expr, index: Index) -> str | None:
    """The dotted name of the callee: an import's (``json.dump``), or ``builtins.<name>`` for a
    name the module binds nowhere."""
    if isinstance(func, ast.Name) and func.id not in index.bound:
        return f"builtins.{func.id}"
    return index.qualified(func) if isinstance(func, (ast.Name, ast.Attribute)) else None


def _probing(call: ast.Call, index: Index) -> bool:
    """True inside a ``try`` whose handlers catch TypeError (or everything)."""
    child, parent = call, index.parents.get(id(call))
    while parent is not None:
        if isinstance(parent, TRIES) and child in parent.body and any(
                handler.type is None or any(
                    isinstance(n, ast.Name) and n.id in ("TypeError", "Exception",
                                                         "BaseException")
                    for n in ast.walk(handler.type))
                for handler in parent.handlers):
            return True
        child, parent = parent, index.parents.get(id(parent))
    return False
