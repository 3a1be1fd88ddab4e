"""LCH025: a launch file gives ``robot_description`` the path of a robot model, or the text of a
xacro file xacro never ran on, where a node wants URDF text."""

from __future__ import annotations

import ast
import re
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity, shortened
from pkgtool.lazy_regex import lazy_pattern
from pkgtool.model.ast_nodes import last_name
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.model.text_comments import without_comments
from pkgtool.rules.launch._python_launch import text_argument
from pkgtool.rules.registry import rule
from pkgtool.rules.scopes import single_assignments
from pkgtool.rules.syntax_trees import launch_indexes

_NODES = frozenset({"Node", "LifecycleNode"})
_READERS = frozenset({"robot_state_publisher", "moveit_ros_move_group", "controller_manager"})
"""Packages whose nodes parse ``robot_description`` as URDF text (webots_ros2_driver's takes
a path, as its documentation says)."""
_TEXTS = {"robot_description": "URDF", "robot_description_semantic": "SRDF"}
"""The parameters holding a robot's model, by the kind of text each is."""
_SDF_FIX = "Give the URDF's text: these nodes do not read SDF"
_MODELS = (".urdf", ".xacro", ".sdf", ".srdf")
_PATHS = frozenset({"PathJoinSubstitution", "join", "Path", "PurePath", "joinpath"})
"""Calls building a path (``os.path.join``, ``pathlib.Path``)."""


@rule("LCH025", "robot-description-not-urdf", Severity.ERROR,
      fix="Run xacro on the file: `ParameterValue(Command(['xacro ', path]), value_type=str)` "
          "(or read the text of a plain `.urdf` file)")
def robot_description_not_urdf(package: Package) -> Iterator[Hit]:
    """A node that parses `robot_description` as URDF text is given a file's path, or a raw
    xacro file.

    ## What it does
    In Python launch files, checks the `robot_description` and `robot_description_semantic`
    values of the `parameters=` dicts of nodes of `robot_state_publisher`,
    `moveit_ros_move_group` and `controller_manager` (literal `package=`): reports a path
    to a `.urdf`, `.xacro`, `.sdf` or `.srdf` file (a string literal, `share + '/x.urdf'`,
    `share / 'x.urdf'`, an f-string, `os.path.join(...)`, `PathJoinSubstitution([...])` or
    `Path(...)` whose last part is such a file name, also through a name bound once, or
    inside `ParameterValue(...)`; the dict given in place or by a name bound once), and the
    text of a `.xacro` file read as it is (`open(path).read()`, `f.read()` of `with
    open(path) as f`, `Path(path).read_text()`), unless the package's files of that name need
    no expansion (only `<xacro:arg>` and `<xacro:property>` declarations, which the URDF
    parser skips as it skips `<gazebo>` elements). `Command(['xacro ', path])` and
    `xacro.process_file(path).toxml()` are what these nodes want.

    ## Why is this bad?
    The value is the robot's URDF, not where to find it: robot_state_publisher fails to
    parse a path ("Unable to initialize urdf::model from robot_description") and exits, and
    move_group cannot load the robot model. A xacro file's `${...}` expressions and
    `<xacro:...>` macros are no URDF either until xacro has run.

    ## Example
    ```python
    model = PathJoinSubstitution([FindPackageShare('my_robot'), 'urdf', 'robot.urdf.xacro'])
    Node(package='robot_state_publisher', executable='robot_state_publisher',
         parameters=[{'robot_description': model}])
    ```

    ## Use instead
    ```python
    description = ParameterValue(Command(['xacro ', model]), value_type=str)
    Node(package='robot_state_publisher', executable='robot_state_publisher',
         parameters=[{'robot_description': description}])
    ```
    """
    for path, index in launch_indexes(package):
        nodes = [call for call in index.calls if last_name(call.func) in _NODES and
                 text_argument(call, "package") in _READERS]
        if not nodes:
            continue
        module = index.module_of(nodes[0])
        at_top = {**_opened_as(module), **single_assignments(module)}
        scopes: dict[int, dict[str, ast.expr]] = {}  # each function's names, worked out once
        for call in nodes:
            function = index.enclosing_function(call)
            names = at_top if function is None else scopes.setdefault(id(function), {
                **at_top, **_opened_as(function), **single_assignments(function)})
            for key, value in _description_values(call, names):
                what = _what(value, names, package)
                if what is not None:
                    yield Hit(Span(path, value.lineno, value.col_offset + 1),
                              f"`{key}` is given {what} (`{shortened(ast.unparse(value))}`), "
                              f"but `{text_argument(call, 'package')}` parses the value as "
                              f"{_TEXTS[key]} text: the node fails to load the robot model",
                              _SDF_FIX if what.endswith(".sdf`") else None)


_XACRO_AT_WORK = lazy_pattern(r"\$\{|\$\(|<xacro:(?!arg\b|property\b)")
"""What xacro must expand before a URDF parser sees the model: an expression, a
substitution, a tag other than an argument's or a property's declaration (a macro, a call
of one, an include, a condition)."""
_GAZEBO = lazy_pattern(r"<gazebo\b.*?</gazebo>", re.S)
"""A ``<gazebo>`` element, which the URDF parser skips (its plugins' ``$(find ...)``)."""


def _plain_urdf(package: Package, name: str) -> bool:
    """True when every xacro file of the package called ``name`` needs no expansion: only
    ``<xacro:arg>``/``<xacro:property>`` declarations (ignored by the URDF parser, as
    ``<gazebo>`` elements are), no ``${}``, no macro."""
    texts = [package.texts.get(path) for path in package.files
             if path.rpartition("/")[2] == name]
    return bool(texts) and all(text is not None and not _XACRO_AT_WORK.search(
        _GAZEBO.sub("", without_comments(text, "xml"))) for text in texts)


def _opened_as(where: ast.AST) -> dict[str, ast.expr]:
    """The names ``with open(path) as f:`` binds in ``where``, with what they are bound to."""
    return {item.optional_vars.id: item.context_expr for node in ast.walk(where)
            if isinstance(node, (ast.With, ast.AsyncWith)) for item in node.items
            if isinstance(item.optional_vars, ast.Name)}


def _description_values(call: ast.Call, names: dict[str, ast.expr]
                        ) -> Iterator[tuple[str, ast.expr]]:
    """(key, value) of the ``robot_description`` entries of the node's ``parameters=``
    dicts (written there, or bound once to a name given there)."""
    given = next((k.value for k in call.keywords if k.arg == "parameters"), None)
    for item in given.elts if isinstance(given, (ast.List, ast.Tuple)) else ():
        item = _resolved(item, names)
        if isinstance(item, ast.Dict):
            for key, value in zip(item.keys, item.values):
                if isinstance(key, ast.Constant) and key.value in _TEXTS:
                    yield key.value, value


def _what(value: ast.expr, names: dict[str, ast.expr], package: Package) -> str | None:
    """What a ``robot_description`` value is, when it is no URDF text: "the path of ..."
    or "the unprocessed text of ..." (a xacro file of the package needing no expansion is
    URDF text); None otherwise (or not known)."""
    value = _resolved(value, names)
    if isinstance(value, ast.Call) and last_name(value.func) == "ParameterValue" and value.args:
        value = _resolved(value.args[0], names)
    model = _model_file(value, names)
    if model is not None:
        return f"the path of `{model}`"
    if isinstance(value, ast.Call) and isinstance(value.func, ast.Attribute) and \
            value.func.attr in ("read", "read_text"):
        opened = _resolved(value.func.value, names)
        source = opened.args[0] if isinstance(opened, ast.Call) and opened.args and \
            last_name(opened.func) in ("open", "Path") else None
        read = _model_file(source, names) if source is not None else None
        if read is not None and read.endswith(".xacro") and not _plain_urdf(package, read):
            return f"the unprocessed text of `{read}`"
    return None


def _resolved(value: ast.expr, names: dict[str, ast.expr]) -> ast.expr:
    """The value a name bound once stands for, else ``value``."""
    return names.get(value.id, value) if isinstance(value, ast.Name) else value


def _model_file(value: ast.expr, names: dict[str, ast.expr], depth: int = 0) -> str | None:
    """The robot model file name a path expression ends in (``robot.urdf.xacro``: a text,
    ``share / 'x.urdf'``, ``share + '/x.urdf'``, ``f'{share}/x.urdf'`` or a joining call),
    or None."""
    value = _resolved(value, names)
    if depth > _DEPTH:
        return None  # names bound to each other
    if isinstance(value, ast.Constant) and isinstance(value.value, str):
        last = value.value.rstrip("/").rpartition("/")[2]
        return last if last.endswith(_MODELS) and "\n" not in value.value else None
    if isinstance(value, ast.BinOp) and isinstance(value.op, (ast.Div, ast.Add)):
        return _model_file(value.right, names, depth + 1)
    if isinstance(value, ast.JoinedStr) and value.values:
        return _model_file(value.values[-1], names, depth + 1)
    if isinstance(value, ast.Call) and last_name(value.func) in _PATHS:
        parts = value.args
        if len(parts) == 1 and isinstance(parts[0], (ast.List, ast.Tuple)):
            parts = parts[0].elts  # PathJoinSubstitution([...])
        return _model_file(parts[-1], names, depth + 1) if parts else None
    return None


_DEPTH = 20
"""How many names and parts a path is followed through."""
