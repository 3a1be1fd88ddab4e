"""LCH010: a launch action or description called with arguments launch rejects."""

from __future__ import annotations

import ast
import shlex
from difflib import get_close_matches
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.launch._python_launch import launch_class, within
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, launch_indexes

DECLARE_KEYWORDS = ("name", "default_value", "description", "choices", "condition")
"""The keywords ``DeclareLaunchArgument`` takes (``condition`` is every action's)."""
ACTION_MODULES = ("launch.actions", "launch_ros.actions")
"""The modules whose classes are all actions."""
BY_KEYWORD = "Write `default_value=...`"
ITEMS = "Pass `{...}.items()`"
IN_A_LIST = "Write `LaunchDescription([{}(...)])`"
CMD_BY_KEYWORD = "Write `cmd=[...]`"
"""Fixes the fixer of LCH010 knows how to apply (besides renamed keywords and quoted text)."""


def _not_text(value: ast.expr) -> ast.Constant | None:
    """The number or bool a ``default_value`` is, or holds in its list, else None."""
    items = value.elts if isinstance(value, (ast.List, ast.Tuple)) else [value]
    return next((item for item in items if isinstance(item, ast.Constant)
                 and item.value is not None and not isinstance(item.value, str)), None)


def _declare(call: ast.Call, _: Index) -> Iterator[tuple[ast.AST, str, str]]:
    if len(call.args) > 1 and not any(isinstance(a, ast.Starred) for a in call.args):
        yield (call.args[1], "`DeclareLaunchArgument()` takes its default by keyword only: "
               "a second positional argument raises TypeError", BY_KEYWORD)
    for keyword in call.keywords:
        meant = next((k for k in DECLARE_KEYWORDS if k.startswith(keyword.arg or "_")), None) \
            or next(iter(get_close_matches(keyword.arg or "", DECLARE_KEYWORDS, n=1)), None)
        if keyword.arg is not None and keyword.arg not in DECLARE_KEYWORDS:
            yield (keyword, f"`DeclareLaunchArgument()` has no `{keyword.arg}` argument: it "
                   "raises TypeError when the launch file is loaded",
                   f"Write `{meant}=`" if meant else
                   f"Pass only {', '.join(f'`{k}`' for k in DECLARE_KEYWORDS[1:])}")
        number = _not_text(keyword.value) if keyword.arg == "default_value" else None
        if number is not None:
            text = str(number.value).lower() if isinstance(number.value, bool) \
                else str(number.value)
            yield (number, f"`default_value` holds `{number.value!r}`, not a string: "
                   "DeclareLaunchArgument raises TypeError (launch arguments are text)",
                   f"Write `'{text}'`")


def _include(call: ast.Call, _: Index) -> Iterator[tuple[ast.AST, str, str]]:
    value = next((k.value for k in call.keywords if k.arg == "launch_arguments"), None)
    pairs = isinstance(value, ast.Dict) and all(
        isinstance(key, ast.Constant) and isinstance(key.value, str) and len(key.value) == 2
        for key in value.keys)
    if isinstance(value, (ast.Dict, ast.DictComp)) and not pairs:
        yield (value, "`launch_arguments=` is a dict: IncludeLaunchDescription iterates its "
               "keys as (name, value) pairs and fails", ITEMS)


def _description(call: ast.Call, index: Index) -> Iterator[tuple[ast.AST, str, str]]:
    entity = call.args[0] if call.args else None
    module, made = launch_class(entity, index) if isinstance(entity, ast.Call) else ("", "")
    if within(module, ACTION_MODULES) and made[:1].isupper():
        yield (entity, f"`LaunchDescription()` is given one `{made}`, not a list: it raises "
               f"TypeError ('{made}' object is not iterable)",
               IN_A_LIST.format(made))


def _path_join(call: ast.Call, _: Index) -> Iterator[tuple[ast.AST, str, str]]:
    if len(call.args) > 1 and not any(isinstance(a, ast.Starred) for a in call.args):
        parts = ", ".join(ast.unparse(a) for a in call.args)
        yield (call.args[1], f"`PathJoinSubstitution()` takes one list of parts but is given "
               f"{len(call.args)} arguments: it raises TypeError", f"Write `[{parts}]`")


_EXECUTABLE_LOOKUPS = frozenset({"FindExecutable", "ExecutableInPackage"})


_DATA_SUFFIXES = (".urdf", ".xacro", ".sdf", ".srdf", ".yaml", ".yml", ".xml", ".rviz",
                  ".world", ".json")
"""Suffixes of the data files a launch file reads, never of a program."""


def _command(call: ast.Call, index: Index) -> Iterator[tuple[ast.AST, str, str]]:
    """``Command(['xacro', path])``: the program and its first argument joined into one word
    (launch concatenates the parts as they are); ``Command([urdf_path])``: a data file run
    as the program."""
    if len(call.args) > 1 and not any(isinstance(a, ast.Starred) for a in call.args):
        words = ", ".join(ast.unparse(a) for a in call.args)
        yield (call.args[1], f"`Command()` takes the command as one argument (a string or a "
               f"list of parts; `on_stderr` is keyword-only) but is given {len(call.args)}: "
               "it raises TypeError", f"Write `Command([{words}])`, with the spaces between "
               "the words in the parts")
        return
    parts = call.args[0] if call.args else None
    first_part = parts.elts[0] if isinstance(parts, (ast.List, ast.Tuple)) and parts.elts \
        else parts
    data = _data_file(first_part, index) if first_part is not None else None
    if data is not None:
        yield (first_part, f"`Command()` runs its first word as a program, and that is the data "
               f"file `{data}`: running it fails (PermissionError, or 'Exec format error'), "
               "and the launch stops", "Run the program that reads it: "
               "`Command(['xacro ', path])` for a URDF or xacro file")
    if not isinstance(parts, (ast.List, ast.Tuple)) or len(parts.elts) < 2:
        return
    first, second = parts.elts[:2]
    spaced = isinstance(second, ast.Constant) and isinstance(second.value, str) and \
        second.value[:1].isspace()
    if spaced or isinstance(second, ast.Starred):
        return
    if isinstance(first, ast.Constant) and isinstance(first.value, str) and first.value and \
            not first.value[-1].isspace() and " " not in first.value.strip() and \
            not (isinstance(second, ast.Constant) and isinstance(second.value, str)):
        yield (first, f"`Command()` joins its parts as they are: `{first.value}` and the part "
               "after it make one word, so the command it runs does not exist",
               f"Write `'{first.value} '`")
    elif isinstance(first, ast.Call) and launch_class(first, index)[1] in _EXECUTABLE_LOOKUPS \
            and not (isinstance(second, ast.Constant) and isinstance(second.value, str)):
        yield (second, "`Command()` joins its parts as they are: the program and this part "
               "make one word, so the command it runs does not exist",
               "Put `' '` between the program and its first argument")


def _data_file(value: ast.expr, index: Index) -> str | None:
    """The name of the data file ``value`` is the path of (a literal, a join of path parts
    ending in one, or a name assigned one of those once), else None."""
    if isinstance(value, ast.Name):
        scope: ast.AST = index.enclosing_function(value) or index.module_of(value)
        values = [node.value for node in nodes_of_class(scope, ast.Assign)
                  if isinstance(node, ast.Assign) and any(
                      isinstance(t, ast.Name) and t.id == value.id for t in node.targets)]
        value = values[0] if len(values) == 1 else value
    if isinstance(value, ast.Call) and value.args:  # os.path.join, PathJoinSubstitution
        last = value.args[-1]
        value = last.elts[-1] if isinstance(last, (ast.List, ast.Tuple)) and last.elts else last
    if isinstance(value, ast.Constant) and isinstance(value.value, str) and \
            " " not in value.value.strip() and value.value.strip().endswith(_DATA_SUFFIXES):
        return value.value.strip().rsplit("/", 1)[-1]
    return None


SHELL_SIGNS = frozenset("|&;<>()$`*?~")
"""Characters whose meaning a shell gives and a list of words would lose or change."""
SPLIT_UNCERTAIN = frozenset("'\"\\\n#")
"""Characters that make splitting a command into words uncertain, shell or not (quoting, a
second line, a comment)."""


def _execute_process(call: ast.Call, _: Index) -> Iterator[tuple[ast.AST, str, str]]:
    """``ExecuteProcess(['ls'])`` (``cmd`` is keyword-only) and ``cmd='ros2 bag play x'``:
    one string, whose characters launch takes as the command's words."""
    shell = any(k.arg == "shell" and isinstance(k.value, ast.Constant) and k.value.value is True
                for k in call.keywords)
    keyword = next((k for k in call.keywords if k.arg == "cmd"), None)
    if call.args and not any(isinstance(a, ast.Starred) for a in call.args):
        first = call.args[0]
        text = _text(first)
        alone = len(call.args) == 1 and keyword is None  # `cmd=` can be written before it
        yield (first, "`ExecuteProcess()` takes its command by keyword only, as a list of "
               "words: a positional argument raises TypeError",
               (_words(text, shell) if text is not None or isinstance(first, ast.JoinedStr)
                else CMD_BY_KEYWORD) if alone else "Pass the command as `cmd=[...]` and the "
               "other arguments by keyword")
    text = _text(keyword.value) if keyword else None
    if keyword is None or text is None and not isinstance(keyword.value, ast.JoinedStr) or \
            text is not None and len(text.strip()) < 2:
        return
    program = f"`{text.strip()[0]}`" if text else "after its first character"
    yield (keyword, "`cmd=` of `ExecuteProcess()` is one string, not a list of words: launch "
           f"takes each character as a word, so it runs a program named {program} and the "
           "process fails to start", _words(text, shell))


def _text(value: ast.expr) -> str | None:
    return value.value if isinstance(value, ast.Constant) and isinstance(value.value, str) \
        else None


def _words(text: str | None, shell: bool) -> str:
    """The fix of a command written as one string: its words, where splitting it is certain
    (none of :data:`SPLIT_UNCERTAIN`, and none of :data:`SHELL_SIGNS` unless a shell reads
    the words)."""
    if text is None or SPLIT_UNCERTAIN & set(text) or not shell and SHELL_SIGNS & set(text):
        return ("Pass the words as a list (`cmd=['ros2', 'bag', 'play', path]`), with "
                "`shell=True` for a shell's pipes or `&&`")
    return f"Write `cmd={shlex.split(text)!r}`"


def _condition(call: ast.Call, action: str) -> Iterator[tuple[ast.AST, str, str]]:
    """A ``condition=`` that is a literal (``'true'``, ``True``), an f-string or a lambda, not
    one of launch's conditions."""
    value = next((k.value for k in call.keywords if k.arg == "condition"), None)
    if isinstance(value, ast.Lambda):
        yield (value, f"`condition=` of `{action}()` is a lambda, not a condition: launch "
               "raises AttributeError when it evaluates it ('function' object has no "
               "attribute 'evaluate')", "Write `condition=IfCondition(LaunchConfiguration"
               "('name'))`, or a `launch.conditions` class")
        return
    if isinstance(value, ast.JoinedStr) or isinstance(value, ast.Constant) and \
            value.value is not None:
        shown = ast.unparse(value)
        kind = type(value.value).__name__ if isinstance(value, ast.Constant) else "str"
        text = repr(str(value.value).lower()) if kind == "bool" else shown
        yield (value, f"`condition=` of `{action}()` is `{shown}`, not a condition: launch "
               f"raises AttributeError when it evaluates it ('{kind}' object has no "
               "attribute 'evaluate')", f"Write `condition=IfCondition({text})`")


CHECKS = {"DeclareLaunchArgument": ("launch.actions", _declare),
          "IncludeLaunchDescription": ("launch.actions", _include),
          "LaunchDescription": ("launch", _description),
          "PathJoinSubstitution": ("launch.substitutions", _path_join),
          "Command": ("launch.substitutions", _command),
          "ExecuteProcess": ("launch.actions", _execute_process)}
"""Class -> (the module it is in, or a package holding it; its check)."""


@rule("LCH010", "invalid-launch-action-argument", Severity.ERROR,
      fix="Pass the arguments the launch class takes (see the message)")
def invalid_launch_action_argument(package: Package) -> Iterator[Hit]:
    """A Python launch file gives a launch action or description arguments it rejects.

    ## What it does
    Checks calls of `launch` classes in Python launch files (names bound by imports from
    `launch` only): `DeclareLaunchArgument` with a default that is not text
    (`default_value=False`, `default_value=0.5`, or a list holding a number), with its
    default as a second positional argument (it is keyword-only), or with a shortened
    keyword (`default=`, `desc=`); `IncludeLaunchDescription` with `launch_arguments=`
    written as a dict (display or comprehension) instead of its `.items()`; and
    `LaunchDescription` given one action (`LaunchDescription(Node(...))`) instead of a list;
    and `PathJoinSubstitution` given its parts as separate arguments instead of one list;
    and `Command` given its words as separate arguments (`Command('ros2', 'run', ...)`; it
    takes one, `on_stderr` is keyword-only), or its program and first argument with no
    space between (`Command(['xacro', path])`, `Command([FindExecutable(name='xacro'),
    path])`), or a data file as its program (`Command([urdf_path])`, the path of a `.urdf`,
    `.xacro`, `.yaml` ... file, written or joined in the call or assigned once to the name);
    and `ExecuteProcess` given its command positionally (`cmd` is keyword-only) or as one
    string (`cmd='ros2 bag play run1'`, an f-string too) instead of a list of words;
    and any action of `launch.actions` or `launch_ros.actions` given a literal or f-string as
    `condition=` (`condition='true'`) instead of a condition (`IfCondition(...)`). Only
    literals and displays are judged: a dict held in a variable is not.

    ## Why is this bad?
    `ros2 launch` fails: `DeclareLaunchArgument` raises `TypeError` when the file is loaded
    (launch arguments are strings or substitutions; its default is keyword-only; it has no
    `default` argument); `IncludeLaunchDescription` iterates a dict's keys and fails to
    unpack each as a (name, value) pair when it runs ("too many values to unpack"); a
    `LaunchDescription` cannot iterate an action; `Command` runs `xacro/home/.../robot.urdf`,
    which does not exist; `ExecuteProcess` iterates its command, so a string becomes one
    word per character and the program it runs is its first letter; and an action calls its
    condition's `evaluate()`, which a string does not have.

    ## Example
    ```python
    DeclareLaunchArgument('use_sim_time', default_value=False),
    IncludeLaunchDescription(source, launch_arguments={'use_sim_time': 'true'}),
    ```

    ## Use instead
    ```python
    DeclareLaunchArgument('use_sim_time', default_value='false'),
    IncludeLaunchDescription(source, launch_arguments={'use_sim_time': 'true'}.items()),
    ```
    """
    for path, index in launch_indexes(package):
        for call in index.calls:
            module, name = launch_class(call, index)
            home, check = CHECKS.get(name, ("-", None))
            found = check(call, index) if check and within(module, (home,)) else ()
            if within(module, ACTION_MODULES) and name[:1].isupper():
                found = (*found, *_condition(call, name))
            for node, message, fix in found:
                yield Hit(Span(path, node.lineno, node.col_offset + 1),  # type: ignore
                          message, fix)
