"""LCH008: a launch configuration read under a misspelling of a declared argument."""

from __future__ import annotations

import ast
import re
from collections.abc import Iterator
from difflib import get_close_matches

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import last_name, nodes_of_class
from pkgtool.model.launch_reader import VARIABLE_READ
from pkgtool.model.package import Package
from pkgtool.model.text_comments import without_comments
from pkgtool.model.python_visitor import parse_tree
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule
from pkgtool.rules.launch._python_launch import text_argument
from pkgtool.rules.syntax_trees import python_launch_files

_DECLARE = "DeclareLaunchArgument"
_READ = "LaunchConfiguration"
_FRONTEND_DECLARED = (re.compile(r"<(?:arg|let)\b[^>]*?\bname\s*=\s*[\"']([^\"']+)[\"']"),
                      re.compile(r"^\s*-?\s*(?:arg|let):\s*\n\s+name:\s*[\"']?([\w.-]+)",
                                 re.M))
"""An XML (``<arg name="x">``, ``<let name="x">``) or YAML (``- arg:`` / ``name: x``)
launch file's declared or set arguments."""


@rule("LCH008", "misspelled-launch-argument", Severity.ERROR,
      fix="Read the argument under the name it is declared with")
def misspelled_launch_argument(package: Package) -> Iterator[Hit]:
    """A launch file reads a launch configuration that nothing declares, under a name spelled
    almost like a declared argument.

    ## What it does
    In the package's Python launch files, collects the names declared with
    `DeclareLaunchArgument('name', ...)` (in any of them) and reports
    `LaunchConfiguration('other')` without a `default` when `other` is declared nowhere,
    nothing else in the files sets it (`SetLaunchConfiguration`, `launch_arguments`) and
    a declared name of the same file is spelled almost the same (`use_sim_tim` for
    `use_sim_time`). In XML and YAML launch files, the same for `$(var other)` against the
    names of `<arg>` and `<let>` (`arg:` and `let:`), when `other` appears nowhere else in
    the file.

    ## Why is this bad?
    `ros2 launch` fails when it evaluates the substitution: `launch configuration
    'use_sim_tim' does not exist`, unless the user happens to pass that misspelt name on the
    command line. The declared argument is never used.

    ## Example
    ```python
    DeclareLaunchArgument('use_sim_time', default_value='false'),
    Node(..., parameters=[{'use_sim_time': LaunchConfiguration('use_sim_tim')}]),
    ```

    ## Use instead
    ```python
    DeclareLaunchArgument('use_sim_time', default_value='false'),
    Node(..., parameters=[{'use_sim_time': LaunchConfiguration('use_sim_time')}]),
    ```
    """
    files = [(path, parse_tree(path, text), text) for path, _, text in
             python_launch_files(package)]
    frontends = [(launch.path, without_comments(text, launch.kind))
                 for launch in package.launch_files
                 if launch.kind in ("xml", "yaml") and launch.problem is None and
                 (text := package.texts.get(launch.path)) is not None]
    declared_anywhere = {name for _, text in frontends for pattern in _FRONTEND_DECLARED
                         for name in pattern.findall(text)}
    calls: dict[str, list[ast.Call]] = {}
    for path, tree, _ in files:
        found = nodes_of_class(tree, ast.Call) if isinstance(tree, ast.Module) else []
        calls[path] = found
        declared_anywhere.update(name for c in found if last_name(c.func) == _DECLARE
                                 and (name := text_argument(c, "name")) is not None)
    for path, _, text in files:
        declared = {name for c in calls[path] if last_name(c.func) == _DECLARE
                    and (name := text_argument(c, "name")) is not None}
        for call in calls[path]:
            name = text_argument(call, "variable_name") if last_name(call.func) == _READ else None
            if name is None or name in declared_anywhere or len(call.args) > 1 or any(
                    k.arg == "default" for k in call.keywords) or \
                    text.count(f"'{name}'") + text.count(f'"{name}"') > 1:
                continue
            close = get_close_matches(name, sorted(declared), n=1, cutoff=0.8)
            if close:
                yield _hit(Span(path, call.lineno, call.col_offset + 1), name, close[0])
    for path, text in frontends:
        declared = {name for pattern in _FRONTEND_DECLARED for name in pattern.findall(text)}
        for read in VARIABLE_READ.finditer(text):
            name = read.group(1)
            if name in declared_anywhere or len(re.findall(
                    rf"(?<![\w.-]){re.escape(name)}(?![\w.-])", text)) > 1:
                continue
            close = get_close_matches(name, sorted(declared), n=1, cutoff=0.8)
            if close:
                yield _hit(Span.of_offset(path, text, read.start()), name, close[0])


def _hit(span: Span, name: str, meant: str) -> Hit:
    return Hit(span, f"`{name}` is declared by no launch argument (did you mean `{meant}`?): "
                     f"the launch fails with launch configuration '{name}' does not exist")
