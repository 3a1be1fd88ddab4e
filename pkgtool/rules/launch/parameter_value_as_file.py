"""LCH021: a value in a node's ``parameters=`` list, which launch_ros takes for a file path."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity, shortened
from pkgtool.model.ast_nodes import last_name
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.launch._python_launch import text_argument
from pkgtool.rules.registry import rule
from pkgtool.rules.scopes import single_assignments
from pkgtool.rules.syntax_trees import launch_indexes

_NODES = frozenset({"Node", "ComposableNode", "LifecycleNode"})
_BOOLEANS = frozenset({"true", "false"})


@rule("LCH021", "parameter-value-as-file", Severity.ERROR,
      fix="Give the value under its parameter's name: `parameters=[{'name': value}]`")
def parameter_value_as_file(package: Package) -> Iterator[Hit]:
    """A Python launch file puts a plain value in a node's `parameters=` list.

    ## What it does
    Reports an item of a `parameters=[...]` list of `Node`, `LifecycleNode` or
    `ComposableNode` that is a value rather than a parameter file or a dict: a string
    literal (or a name bound once to one) that is a boolean, a number or a URL, or a bare
    `LaunchConfiguration('x')` whose default (its `default=`, or the `default_value` of the
    file's `DeclareLaunchArgument('x')`) is one (`use_sim_time`'s `'false'`); and a set
    written for a dict (`{'rate: 10'}`: the `:` inside the quotes).

    ## Why is this bad?
    launch_ros takes every string and substitution in the list for the path of a parameter
    file: `'false'` is no file, so it logs "Parameter file path is not a file" and skips it.
    The launch starts, and the node runs without the value it was meant to get.

    ## Example
    ```python
    use_sim_time = LaunchConfiguration('use_sim_time', default='false')
    Node(package='demo', executable='talker', parameters=[use_sim_time])
    ```

    ## Use instead
    ```python
    Node(package='demo', executable='talker', parameters=[{'use_sim_time': use_sim_time}])
    ```
    """
    for path, index in launch_indexes(package):
        lists = [(call, given) for call in index.calls if last_name(call.func) in _NODES
                 for k in call.keywords if k.arg == "parameters"
                 and isinstance(given := k.value, (ast.List, ast.Tuple))]
        if not lists:
            continue
        defaults = _argument_defaults(index.calls)
        at_top = single_assignments(index.module_of(lists[0][0]))
        scopes: dict[int, dict[str, ast.expr]] = {}  # each function's, worked out once
        for call, given in lists:
            function = index.enclosing_function(call)
            local = {} if function is None else scopes.setdefault(
                id(function), single_assignments(function))
            for item in given.elts:
                value = local.get(item.id, at_top.get(item.id)) \
                    if isinstance(item, ast.Name) else item
                if isinstance(value, ast.Set):
                    yield Hit(Span(path, item.lineno, item.col_offset + 1),
                              f"`{shortened(ast.unparse(item))}` in `parameters=` is a set, "
                              "not a dict (the `:` is inside the quotes): launch_ros takes it "
                              "for the path of a parameter file, skips it (\"Parameter file "
                              "path is not a file\") and the node never gets the value",
                              "Write `{'name': value}`")
                    continue
                plain = _plain_value(value, defaults) if value is not None else None
                if plain is not None:
                    yield Hit(Span(path, item.lineno, item.col_offset + 1),
                              f"`{ast.unparse(item)}` in `parameters=` is taken for the path "
                              f"of a parameter file, but it is `{plain}`: launch_ros skips it "
                              "(\"Parameter file path is not a file\") and the node never "
                              "gets the value")


def _argument_defaults(calls: list[ast.Call]) -> dict[str, str | None]:
    """The literal default of each launch argument the file declares (None: several, or
    not a literal)."""
    found: dict[str, str | None] = {}
    for call in calls:
        declares = last_name(call.func) == "DeclareLaunchArgument"
        name = text_argument(call, "name") if declares else None
        if name is not None:
            default = _keyword_text(call, "default_value")
            found[name] = default if found.get(name, default) == default else None
    return found


def _plain_value(value: ast.expr, defaults: dict[str, str | None]) -> str | None:
    """The text ``value`` evaluates to when it is a boolean, number or URL (no file), else
    None."""
    if isinstance(value, ast.Call) and last_name(value.func) == "LaunchConfiguration":
        name = text_argument(value, "variable_name")
        default = _keyword_text(value, "default")
        text = default if default is not None else defaults.get(name or "")
    else:
        text = value.value if isinstance(value, ast.Constant) and \
            isinstance(value.value, str) else None
    return text if text is not None and _no_file(text) else None


def _keyword_text(call: ast.Call, keyword: str) -> str | None:
    """The string literal given as ``keyword=`` (launch's defaults are keyword-only)."""
    value = next((k.value for k in call.keywords if k.arg == keyword), None)
    return value.value if isinstance(value, ast.Constant) and isinstance(value.value, str) \
        else None


def _no_file(text: str) -> bool:
    """True for a boolean, a number or a URL: text no parameter file is named."""
    if text.strip().lower() in _BOOLEANS or "://" in text:
        return True
    try:
        float(text)
    except ValueError:
        return False
    return True
