"""LCH030: a launch file includes a launch file through the source of another format."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule
from pkgtool.rules.scopes import single_assignments
from pkgtool.rules.syntax_trees import Index, launch_trees

_SOURCES = {
    "PythonLaunchDescriptionSource": (".py",),
    "XMLLaunchDescriptionSource": (".xml",),
    "YAMLLaunchDescriptionSource": (".yaml", ".yml"),
    "FrontendLaunchDescriptionSource": (".xml", ".yaml", ".yml"),
}
"""The launch description sources, by class name, and the suffixes of the files each reads."""
_LAUNCH_SUFFIXES = (".py", ".xml", ".yaml", ".yml")
_MODULES = ("launch.launch_description_sources", "launch_xml.launch_description_sources",
            "launch_yaml.launch_description_sources")
_RIGHT = {".py": "PythonLaunchDescriptionSource", ".xml": "XMLLaunchDescriptionSource",
          ".yaml": "YAMLLaunchDescriptionSource", ".yml": "YAMLLaunchDescriptionSource"}


@rule("LCH030", "launch-source-mismatch", Severity.ERROR,
      fix="Use the source of the file's format, or `AnyLaunchDescriptionSource`")
def launch_source_mismatch(package: Package) -> Iterator[Hit]:
    """A launch file includes a launch file with the description source of another format.

    ## What it does
    Reports `PythonLaunchDescriptionSource(path)` whose path's last part (a literal, the
    last element of a `PathJoinSubstitution` or `os.path.join`, a substitution list's last
    text, or a name bound once to one of those) ends in `.xml`, `.yaml` or `.yml`, and
    `XMLLaunchDescriptionSource`, `YAMLLaunchDescriptionSource` or
    `FrontendLaunchDescriptionSource` given a file of another format (`.py`, `.xml` for
    YAML's). `AnyLaunchDescriptionSource` reads every format and is never reported.

    ## Why is this bad?
    A Python source runs the file as Python: an XML launch file fails with a SyntaxError at
    `<launch>`; an XML or YAML source fails to parse a Python file. The include fails
    whenever it is reached (often only under a condition, so it goes unseen).

    ## Example
    ```python
    IncludeLaunchDescription(PythonLaunchDescriptionSource(
        PathJoinSubstitution([FindPackageShare('my_robot'), 'launch', 'camera.launch.xml'])))
    ```

    ## Use instead
    ```python
    IncludeLaunchDescription(XMLLaunchDescriptionSource(
        PathJoinSubstitution([FindPackageShare('my_robot'), 'launch', 'camera.launch.xml'])))
    ```
    """
    for path, _, index in launch_trees(package):
        for call in index.calls:
            source = _source_class(call, index)
            given = call.args[0] if call.args else next(
                (k.value for k in call.keywords if k.arg == "launch_file_path"), None)
            name = _last_text(given, call, index, 0) if source and given is not None else None
            suffix = next((s for s in _LAUNCH_SUFFIXES if name and name.endswith(s)), None)
            if source is None or suffix is None or suffix in _SOURCES[source]:
                continue
            yield Hit(Span(path, call.lineno, call.col_offset + 1),
                      f"`{source}` is given `{name}`, a launch file of another format: the "
                      f"include fails when it is reached",
                      f"Use `{_RIGHT[suffix]}` (or `AnyLaunchDescriptionSource`)")


def _source_class(call: ast.Call, index: Index) -> str | None:
    """The launch description source class ``call`` makes, by name."""
    qualified = index.qualified(call.func) or ""
    module, _, name = qualified.rpartition(".")
    return name if name in _SOURCES and (module in _MODULES or module.startswith(
        _MODULES)) else None


def _last_text(node: ast.expr, at: ast.AST, index: Index, depth: int) -> str | None:
    """The literal text a path expression ends with, when it is plain to see."""
    if depth > 3:
        return None
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return node.value
    if isinstance(node, (ast.List, ast.Tuple)) and node.elts:
        return _last_text(node.elts[-1], at, index, depth + 1)
    if isinstance(node, ast.Call) and node.args and not node.keywords:
        func = node.func
        called = func.id if isinstance(func, ast.Name) else \
            func.attr if isinstance(func, ast.Attribute) else ""
        if called in ("PathJoinSubstitution", "join", "str"):
            return _last_text(node.args[-1], at, index, depth + 1)
    if isinstance(node, ast.BinOp) and isinstance(node.op, (ast.Add, ast.Div)):
        return _last_text(node.right, at, index, depth + 1)
    if isinstance(node, ast.JoinedStr) and node.values:
        return _last_text(node.values[-1], at, index, depth + 1)
    if isinstance(node, ast.Name):
        scope = index.enclosing_function(at) or index.module_of(at)
        bound = single_assignments(scope).get(node.id)
        return _last_text(bound, bound, index, depth + 1) if bound is not None else None
    return None
