"""PYC039: ``rclpy.init()`` called again while the first initialisation still holds."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import is_main_test, subtree
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import INITS, SHUTDOWNS, TRY_SHUTDOWNS
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import FUNCTIONS, Index, installed_trees

_ENDS = SHUTDOWNS | TRY_SHUTDOWNS


def _calls(function: ast.AST, index: Index) -> list[ast.Call]:
    """The calls in ``function``, in source order (nested functions and classes left out)."""
    found = [node for node in subtree(function) if isinstance(node, ast.Call) and
             index.enclosing_function(node, through_lambdas=False) is function]
    return sorted(found, key=lambda call: (call.lineno, call.col_offset))


def _named(call: ast.Call, index: Index, names: frozenset[str]) -> bool:
    return isinstance(call.func, (ast.Name, ast.Attribute)) and \
        index.qualified(call.func) in names


def _certain_init(call: ast.Call, function: ast.AST, index: Index) -> bool:
    """True for ``rclpy.init(...)`` on the default context, a statement of ``function``'s own
    body or of a ``try`` block in it: nothing decides whether it runs."""
    if not _named(call, index, INITS) or any(k.arg == "context" or k.arg is None
                                             for k in call.keywords):
        return False
    statement = index.parents.get(id(call))
    parent = index.parents.get(id(statement)) if isinstance(statement, ast.Expr) else None
    while isinstance(parent, ast.Try) and statement in parent.body:
        statement, parent = parent, index.parents.get(id(parent))
    return parent is function


def _initialising(tree: ast.Module, index: Index) -> dict[str, ast.Call]:
    """Module functions and classes (by the ``__init__`` of the latter) that certainly call
    ``rclpy.init()``: name -> that call."""
    found: dict[str, ast.Call] = {}
    for statement in tree.body:
        body = [statement] if isinstance(statement, FUNCTIONS) else \
            [s for s in statement.body if isinstance(s, FUNCTIONS) and s.name == "__init__"] \
            if isinstance(statement, ast.ClassDef) else []
        for function in body:
            init = next((c for c in _calls(function, index)
                         if _certain_init(c, function, index)), None)
            if init is not None:
                found[statement.name] = init
    return found


def _again(function: ast.AST, index: Index, initialising: dict[str, ast.Call]
           ) -> Iterator[tuple[ast.Call, ast.Call, ast.Call]]:
    """(the first init, the call that initialises again, the init it makes) in ``function``."""
    first: ast.Call | None = None
    for call in _calls(function, index):
        if _named(call, index, _ENDS):
            first = None
        elif first is None:
            first = call if _certain_init(call, function, index) else None
        elif _certain_init(call, function, index):
            yield first, call, call
        elif isinstance(call.func, ast.Name) and call.func.id in initialising and \
                index.qualified(call.func) in (None, call.func.id):
            yield first, call, initialising[call.func.id]


def _named_elsewhere(function: ast.FunctionDef | ast.AsyncFunctionDef, tree: ast.Module
                     ) -> bool:
    """True when the module names ``function`` outside its own body (a top-level call,
    ``fire.Fire(main)``, another function calling it): only a console script may call it."""
    inside = {id(node) for node in ast.walk(function)}
    return any(isinstance(node, ast.Name) and node.id == function.name and
               id(node) not in inside for node in ast.walk(tree))


def _under_main_test(call: ast.Call, function: ast.AST, index: Index) -> bool:
    """True for a call in the body of an ``if __name__ == '__main__':`` of ``function``: run
    as a console script, the module's ``__name__`` is its import name."""
    child, parent = call, index.parents.get(id(call))
    while parent is not None and parent is not function:
        if isinstance(parent, ast.If) and any(child is s for s in parent.body) and \
                is_main_test(parent.test):
            return True
        child, parent = parent, index.parents.get(id(parent))
    return False


@rule("PYC039", "rclpy-initialised-twice", Severity.ERROR,
      fix="Call `rclpy.init()` once, in `main()`, before creating nodes; not in the node class")
def rclpy_initialised_twice(package: Package) -> Iterator[Hit]:
    """`rclpy.init()` is called again while rclpy is already initialised.

    ## What it does
    In installed modules, follows each function that certainly calls `rclpy.init()` (a
    statement of its own body or of a `try` block in it, on the default context) and
    reports a later certain `rclpy.init()` in it, or a later call of a function or class of
    the module whose body (whose `__init__` for a class) certainly calls it, with no
    `rclpy.shutdown()` or `try_shutdown()` in between. Calls given `context=` are not
    judged, nor inits under an `if` (`if not rclpy.ok(): rclpy.init()`), nor a call in the
    body of an `if __name__ == '__main__':` inside a function nothing else in the module names
    (`main()` called there, indented into `main()`: only a console script runs `main()`,
    with another `__name__`).

    ## Why is this bad?
    The default context can be initialised once: the second call raises `RuntimeError:
    Context.init() must only be called once` (checked on Jazzy), so the node dies as it
    starts. It typically happens when a node class calls `rclpy.init()` in its constructor
    and `main()` does too.

    ## Example
    ```python
    class Talker(Node):
        def __init__(self):
            rclpy.init()
            super().__init__('talker')

    def main():
        rclpy.init()
        rclpy.spin(Talker())
    ```

    ## Use instead
    ```python
    class Talker(Node):
        def __init__(self):
            super().__init__('talker')

    def main():
        rclpy.init()
        node = Talker()
        rclpy.spin(node)
    ```
    """
    for module, tree, index in installed_trees(package):
        if not any(i.top_level == "rclpy" for i in module.imports):
            continue
        initialising = _initialising(tree, index)
        for function in (s for s in tree.body if isinstance(s, FUNCTIONS)):
            for first, call, again in _again(function, index, initialising):
                if _under_main_test(call, function, index) and \
                        not _named_elsewhere(function, tree):
                    continue  # `if __name__ == '__main__': main()` indented into main()
                how = "is called again" if call is again else \
                    f"runs again when `{function.name}()` calls `{ast.unparse(call.func)}()` " \
                    f"(line {call.lineno})"
                places = (first,) if call is again else (first, call)
                yield Hit(Span(module.path, again.lineno, again.col_offset + 1),
                          f"`rclpy.init()` {how}, after line {first.lineno} initialised rclpy: "
                          "it raises RuntimeError (the context is initialised once)",
                          related=tuple(Span(module.path, p.lineno, p.col_offset + 1)
                                        for p in places))
