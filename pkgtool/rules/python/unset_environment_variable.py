"""PYC088: ``os.environ.get('X')`` used as a string, though it is None when X is unset."""

from __future__ import annotations

import ast
from collections.abc import Callable, Iterator

from pkgtool.findings import Hit, Severity, shortened
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._assignments import is_none
from pkgtool.rules.registry import rule
from pkgtool.rules.scopes import catches_everything, caught_names, scope_bindings
from pkgtool.rules.syntax_trees import Index, installed_trees, launch_trees

_READERS = frozenset({"os.environ.get", "os.getenv"})
_ALWAYS_SET = frozenset({"HOME", "PATH", "ROS_DISTRO", "ROS_VERSION", "ROS_PYTHON_VERSION",
                         "AMENT_PREFIX_PATH", "PYTHONPATH", "LD_LIBRARY_PATH"})
"""Variables every shell (``HOME``, ``PATH``) or a sourced ROS 2 (``ROS_DISTRO``,
``AMENT_PREFIX_PATH``, ``PYTHONPATH``, ``LD_LIBRARY_PATH``) sets."""
_JOINERS = frozenset({"os.path.join", "pathlib.Path", "int", "float"})
"""Functions refusing None (TypeError)."""
_NUMBERS = frozenset({"int", "float"})


@rule("PYC088", "unset-environment-variable", Severity.WARNING,
      fix="Give a default: `os.environ.get('NAME', '')`, or check the value first")
def unset_environment_variable(package: Package) -> Iterator[Hit]:
    """An environment variable read without a default is used as a string.

    ## What it does
    Reports `os.environ.get('NAME')` and `os.getenv('NAME')` without a default (directly, or
    through a name bound once to it in the same function) used where None fails: an operand
    of `+`, an argument of `os.path.join`, `Path`, `int` or `float`, or the receiver of a
    method (`.split(':')`), in installed modules and Python launch files. Not reported:
    variables every shell or a sourced ROS 2 sets (`HOME`, `PATH`, `ROS_DISTRO`,
    `AMENT_PREFIX_PATH`, `PYTHONPATH`, `LD_LIBRARY_PATH`), a variable the module names
    anywhere else (a test `if 'NAME' in os.environ:`, `os.environ.setdefault('NAME', ...)`,
    a launch `SetEnvironmentVariable('NAME', ...)`), packages with environment hooks
    (`ament_environment_hooks`, a `hooks/x.dsv`: sourcing the install sets their
    variables), a name its function tests (`if value:`, `value or ''`), and code in a `try`
    that catches the error. An explicit `None` default counts as none; `x +=
    os.environ.get('NAME')` is a use of `+`.

    ## Why is this bad?
    `get` returns None for a variable that is not set, and `None + ':'` raises TypeError
    (`.split` AttributeError): the launch file or node dies on any machine where the
    variable is unset, such as `GAZEBO_MODEL_PATH` before Gazebo's setup script is sourced.

    ## Example
    ```python
    os.environ['GAZEBO_MODEL_PATH'] = models + ':' + os.environ.get('GAZEBO_MODEL_PATH')
    ```

    ## Use instead
    ```python
    os.environ['GAZEBO_MODEL_PATH'] = models + ':' + os.environ.get('GAZEBO_MODEL_PATH', '')
    ```
    """
    if _has_environment_hooks(package):
        return  # sourcing the install sets variables of the package's choosing
    trees = [(module.path, tree, index) for module, tree, index in installed_trees(package)]
    for path, tree, index in [*trees, *launch_trees(package)]:
        for call in index.calls:
            name = _variable(call, index)
            if name is None:
                continue
            for use, (how, default) in _none_failing_uses(call, index, tree):
                fix = f"Give a default: `{_with_default(call, default)}`" if default else \
                    f"Check that `{name}` is set first (`if '{name}' in os.environ:`)"
                yield Hit(Span(path, use.lineno, use.col_offset + 1),
                          f"`{shortened(ast.unparse(call))}` is None when `{name}` is not "
                          f"set: {how}", fix)


_HOOK_SUFFIXES = (".dsv", ".sh", ".bash", ".zsh", ".dsv.in", ".sh.in", ".bash.in")


def _has_environment_hooks(package: Package) -> bool:
    """True when the package sets environment variables once its install is sourced: an
    ``ament_environment_hooks`` call, or environment hook files (``hooks/x.dsv``)."""
    return "ament_environment_hooks" in package.texts.get("CMakeLists.txt", "") or any(
        "hook" in path.rpartition("/")[0] and path.endswith(_HOOK_SUFFIXES)
        for path in package.files)


def _variable(call: ast.Call, index: Index) -> str | None:
    """The variable ``call`` reads without a default (``os.environ.get('X')``, also with
    ``None`` as the default), or None."""
    defaults = [*call.args[1:], *(k.value for k in call.keywords)]
    if not call.args or len(defaults) > 1 or any(not is_none(d) for d in defaults) or \
            not isinstance(call.args[0], ast.Constant) or \
            not isinstance(call.args[0].value, str) or \
            not isinstance(call.func, (ast.Name, ast.Attribute)) or \
            index.qualified(call.func) not in _READERS:
        return None
    name = call.args[0].value
    return None if name in _ALWAYS_SET else name


def _with_default(call: ast.Call, default: str) -> str:
    return f"{ast.unparse(call.func)}({ast.unparse(call.args[0])}, {default})"


Failure = tuple[str, str]
"""What using None somewhere raises, and the default to suggest ('' for none: check)."""


def _none_failing_uses(call: ast.Call, index: Index, tree: ast.Module
                       ) -> Iterator[tuple[ast.expr, Failure]]:
    """Where the value of ``call`` is used in a way None fails, with what is raised: the
    call itself, or the reads of a name bound once to it, unless the module names the
    variable elsewhere (a test, ``os.environ.setdefault``, ``SetEnvironmentVariable``) or
    its function tests the name."""
    variable = call.args[0].value  # type: ignore[attr-defined]
    if _named_elsewhere(call, variable, tree, index):
        return
    scope = index.enclosing_function(call) or index.module_of(call)
    values: list[ast.expr] = [call]
    parent = index.parents.get(id(call))
    if isinstance(parent, ast.Assign) and len(parent.targets) == 1 and \
            isinstance(parent.targets[0], ast.Name):
        bound = parent.targets[0].id
        if scope_bindings(scope)[bound] != 1 or \
                _tested(scope, lambda n: isinstance(n, ast.Name) and n.id == bound):
            return
        values = [n for n in ast.walk(scope) if isinstance(n, ast.Name) and n.id == bound and
                  isinstance(n.ctx, ast.Load) and index.enclosing_function(n) is
                  index.enclosing_function(call) and n.lineno >= call.lineno]
    for value in values:
        failure = _failure(value, index)
        if failure is not None and not _caught(value, index, failure[0]):
            yield value, failure


def _named_elsewhere(call: ast.Call, variable: str, tree: ast.Module, index: Index) -> bool:
    """True when the module names ``variable`` elsewhere than in ``call`` and than as the
    target the statement holding the call sets (``os.environ['X'] = a + os.environ.get('X')``
    sets it only after the read)."""
    statement: ast.AST | None = call
    while statement is not None and not isinstance(statement, ast.stmt):
        statement = index.parents.get(id(statement))
    targets = statement.targets if isinstance(statement, ast.Assign) else []
    skipped = {id(n) for target in targets for n in ast.walk(target)} | {id(call.args[0])}
    return any(isinstance(n, ast.Constant) and n.value == variable and id(n) not in skipped
               for n in ast.walk(tree))


def _failure(value: ast.expr, index: Index) -> Failure | None:
    """What using ``value`` (None) where it is raises, or None when it is fine there."""
    parent = index.parents.get(id(value))
    if isinstance(parent, ast.BinOp) and isinstance(parent.op, ast.Add) or \
            isinstance(parent, ast.AugAssign) and isinstance(parent.op, ast.Add) and \
            parent.value is value:
        return "`+` raises TypeError", "''"
    if isinstance(parent, ast.Attribute) and parent.value is value:
        return f"`.{parent.attr}` raises AttributeError", "''"
    if isinstance(parent, ast.Call) and value in parent.args and \
            isinstance(parent.func, (ast.Name, ast.Attribute)):
        func = parent.func
        called = index.qualified(func) or (func.id if isinstance(func, ast.Name) and
                                           func.id not in index.bound else None)
        if called in _JOINERS:
            return f"`{ast.unparse(func)}(...)` raises TypeError", \
                "'0'" if called in _NUMBERS else ""
    return None


def _tested(scope: ast.AST, matches: Callable[[ast.AST], bool]) -> bool:
    """True when a test in ``scope`` (``if``, ``while``, a conditional expression, ``and``/
    ``or``, ``assert``, a comparison) mentions what ``matches``."""
    for node in ast.walk(scope):
        tests = [node.test] if isinstance(node, (ast.If, ast.While, ast.IfExp, ast.Assert)) \
            else [node] if isinstance(node, (ast.BoolOp, ast.Compare)) else []
        if any(matches(n) for test in tests for n in ast.walk(test)):
            return True
    return False


def _caught(node: ast.AST, index: Index, how: str) -> bool:
    """True inside the body of a ``try`` one of whose handlers catches the error ``how``
    names (TypeError or AttributeError), or any."""
    error = "TypeError" if "TypeError" in how else "AttributeError"
    child, parent = node, index.parents.get(id(node))
    while parent is not None:
        if isinstance(parent, ast.Try) and child in parent.body and any(
                catches_everything(h) or error in caught_names(h) for h in parent.handlers):
            return True
        child, parent = parent, index.parents.get(id(parent))
    return False
