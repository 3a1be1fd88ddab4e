"""LCH004: a Python launch file without ``generate_launch_description``."""

from __future__ import annotations

import ast
import posixpath
from collections.abc import Iterator
from difflib import get_close_matches

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import walk_once
from pkgtool.model.package import Package
from pkgtool.model.python_visitor import parse_tree
from pkgtool.model.span import Span
from pkgtool.rules.imports import all_python
from pkgtool.rules.launch._python_launch import FUNCTION
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import python_launch_files

_LOADERS = frozenset({"run_path", "spec_from_file_location", "SourceFileLoader",
                      "load_source", "import_module"})
"""Functions that run or import a Python file named by a string (runpy, importlib, imp)."""


def _required_parameters(path: str, text: str) -> ast.arg | None:
    """The first parameter without a default of the file's top-level launch function."""
    tree = parse_tree(path, text)
    function = next((node for node in getattr(tree, "body", ())
                     if isinstance(node, ast.FunctionDef) and node.name == FUNCTION), None)
    if function is None:
        return None
    arguments = function.args
    positional = [*arguments.posonlyargs, *arguments.args]
    required = positional[:len(positional) - len(arguments.defaults)]
    required += [a for a, d in zip(arguments.kwonlyargs, arguments.kw_defaults) if d is None]
    return required[0] if required else None


def _near_miss(path: str, text: str) -> Span:
    """Where a misspelt launch function is defined, else the top of the file."""
    tree = parse_tree(path, text)
    functions = [node for node in getattr(tree, "body", ())
                 if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef))]
    close = get_close_matches(FUNCTION, [f.name for f in functions], n=1, cutoff=0.7)
    found = next((f for f in functions if close and f.name == close[0]), None)
    return Span(path, found.lineno, found.col_offset + 1) if found else Span(path, 1, 1)


_WRITE_FUNCTION = frozenset({"better_launch"})
"""Launch libraries whose decorator writes the function into the module (better_launch's
``@launch_this``) when ``ros2 launch`` loads it."""


def _loaded_by_others(package: Package) -> dict[str, set[str]]:
    """File name or module name -> the Python files of the package that import it, or run or
    load a file of that name (``runpy.run_path(...'helpers_launch.py')``); tests are left out
    (a test loading a launch file checks it as one)."""
    found: dict[str, set[str]] = {}
    for module in all_python(package):
        if module.is_test:
            continue
        for imported in module.imports:
            found.setdefault(imported.top_level, set()).add(module.path)
        text = package.texts.get(module.path)
        tree = parse_tree(module.path, text) if text is not None and \
            not module.syntax_error else None
        if not isinstance(tree, ast.Module):
            continue
        for call in walk_once(tree).by_class.get(ast.Call, ()):
            func = call.func  # type: ignore[attr-defined]
            if getattr(func, "attr", getattr(func, "id", None)) not in _LOADERS:
                continue
            for node in ast.walk(call):
                if isinstance(node, ast.Constant) and isinstance(node.value, str):
                    found.setdefault(posixpath.basename(node.value), set()).add(module.path)
    return found


def _helper(path: str, loaded: dict[str, set[str]]) -> bool:
    """True when another Python file of the package imports or runs the file at ``path``: a
    helper the launch files share, named like one, that ``ros2 launch`` is not meant to run."""
    name = posixpath.basename(path)
    users = loaded.get(name, set()) | loaded.get(name[:-len(".py")], set())
    return bool(users - {path})


@rule("LCH004", "missing-launch-function", Severity.ERROR,
      fix="Define `def generate_launch_description():` returning a `LaunchDescription`")
def missing_launch_function(package: Package) -> Iterator[Hit]:
    """A Python launch file does not define `generate_launch_description`.

    ## What it does
    Reports Python launch files (`*.launch.py`, `*_launch.py`) that neither define nor import
    a top-level `generate_launch_description`, at a function whose name is close to it when
    there is one. Test files (`launch_testing` files define `generate_test_description`),
    files with a star import, files of launch libraries whose decorator writes the function
    when `ros2 launch` loads them (better_launch's `@launch_this`), and helpers that another
    Python file of the package (not a test)
    imports or runs (`import shared_launch`, `runpy.run_path(... 'nodes_launch.py')`,
    `importlib.util.spec_from_file_location`) are not checked. Also reports a
    `generate_launch_description` that requires a parameter (`def
    generate_launch_description(context):`): `ros2 launch` calls it with none.

    ## Why is this bad?
    `ros2 launch` imports the file and calls that function by name; without it the launch
    stops with "launch file ... does not contain the required function".

    ## Example
    ```python
    def generate_launch_descriptions():
        return LaunchDescription([Node(package='my_pkg', executable='talker')])
    ```

    ## Use instead
    ```python
    def generate_launch_description():
        return LaunchDescription([Node(package='my_pkg', executable='talker')])
    ```
    """
    loaded: dict[str, set[str]] | None = None
    for path, module, text in python_launch_files(package):
        names = module.top_level_names
        required = _required_parameters(path, text) if FUNCTION in names else None
        if required is not None:
            yield Hit(Span(path, required.lineno, required.col_offset + 1),
                      f"`{FUNCTION}()` requires `{required.arg}`: `ros2 launch` calls it with no "
                      "arguments, and Python raises TypeError",
                      f"Give `{required.arg}` a default, or remove it")
        if FUNCTION in names or "generate_test_description" in names or \
                any("*" in i.names or i.top_level in _WRITE_FUNCTION for i in module.imports):
            continue
        loaded = _loaded_by_others(package) if loaded is None else loaded
        if _helper(path, loaded):
            continue
        yield Hit(_near_miss(path, text),
                  f"`{path}` defines no `{FUNCTION}()`: `ros2 launch` cannot run it")
