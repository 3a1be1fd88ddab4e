"""LCH004: a Python launch file without ``generate_launch_description``."""

from __future__ import annotations

import ast
from collections.abc import Iterator
from difflib import get_close_matches

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.python_visitor import parse_tree
from pkgtool.model.span import Span
from pkgtool.rules.launch._python_launch import FUNCTION, python_launch_files
from pkgtool.rules.registry import rule


def _near_miss(path: str, text: str) -> Span:
    """Where a misspelt launch function is defined, else the top of the file."""
    tree = parse_tree(path, text)
    functions = [node for node in getattr(tree, "body", ())
                 if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef))]
    close = get_close_matches(FUNCTION, [f.name for f in functions], n=1, cutoff=0.7)
    found = next((f for f in functions if close and f.name == close[0]), None)
    return Span(path, found.lineno, found.col_offset + 1) if found else Span(path, 1, 1)


@rule("LCH004", "missing-launch-function", Severity.ERROR,
      fix="Define `def generate_launch_description():` returning a `LaunchDescription`")
def missing_launch_function(package: Package) -> Iterator[Hit]:
    """A Python launch file does not define `generate_launch_description`.

    ## What it does
    Reports Python launch files (`*.launch.py`, `*_launch.py`) that neither define nor import
    a top-level `generate_launch_description`, at a function whose name is close to it when
    there is one. Test files (`launch_testing` files define `generate_test_description`) and
    files with a star import are not checked.

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
    for path, module, text in python_launch_files(package):
        names = module.top_level_names
        if FUNCTION in names or "generate_test_description" in names or \
                any("*" in i.names for i in module.imports):
            continue
        yield Hit(_near_miss(path, text),
                  f"`{path}` defines no `{FUNCTION}()`: `ros2 launch` cannot run it")
