"""LCH028: a launch file hands a launch file it includes an argument that file never reads."""

from __future__ import annotations

import ast
from collections.abc import Iterator
from difflib import get_close_matches

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.model.launch import LaunchFile
from pkgtool.model.launch_reader import FRONTEND_DECLARED
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.model.text_comments import without_comments
from pkgtool.lazy_regex import lazy_pattern
from pkgtool.rules.launch._python_launch import (DESCRIPTION, READ_BY_LAUNCH, literal_arguments,
                                                 reads_shown)
from pkgtool.rules.launch_includes import own_includes
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, launch_indexes


@rule("LCH028", "unread-include-argument", Severity.WARNING,
      fix="Hand the argument under a name the included launch file declares, or to the "
          "launch file that reads it")
def unread_include_argument(package: Package) -> Iterator[Hit]:
    """A launch file hands a launch file of its own package, which it includes, an argument
    that file never reads.

    ## What it does
    For each `IncludeLaunchDescription` of a Python launch file, and each `<include>` of an
    XML one, whose file is a launch file this package installs
    (`os.path.join(get_package_share_directory('<pkg>'), 'launch', 'robot.launch.py')`,
    `PathJoinSubstitution([FindPackageShare('<pkg>'), ...])`, `$(find-pkg-share <pkg>)/...`),
    reads the names handed on (`launch_arguments=`: a dict, `dict.items()` or a list of pairs,
    with literal keys; `<arg name=...>`) and reports each name the included file does not
    declare (`DeclareLaunchArgument`, `<arg>`), read (`LaunchConfiguration`, `$(var x)`) or
    write anywhere else, and says which declared name it may misspell: one spelled almost the
    same (`use_sim_tme` for `use_sim_time`) or the same with a word more or less (`params`
    for `params_file`) that the include does not hand on too. Included files that may read
    configurations where the file does not show it are left alone: Python ones not read as
    LCH024 reads them (includes of their own, an `OpaqueFunction`, conditions taking a name,
    helpers of other modules, parameter files with substitutions), XML and YAML ones
    including others. `launch-prefix` and `emulate_tty`, which launch reads itself, are left
    alone.

    ## Why is this bad?
    Launch accepts any name there and says nothing: the included file runs with its own
    default (`use_sim_time` stays false, the robot keeps its default name, the world meant
    for the simulator is never loaded) while the including file looks as if it set it.

    ## Example
    ```python
    IncludeLaunchDescription(
        PythonLaunchDescriptionSource(os.path.join(share, 'launch', 'robot.launch.py')),
        launch_arguments={'use_sim_tme': 'true'}.items())
    ```

    ## Use instead
    ```python
    IncludeLaunchDescription(
        PythonLaunchDescriptionSource(os.path.join(share, 'launch', 'robot.launch.py')),
        launch_arguments={'use_sim_time': 'true'}.items())
    ```
    """
    launches = {launch.path: launch for launch in package.launch_files}
    indexes = dict(launch_indexes(package))
    for include in own_includes(package):
        used = _arguments_used(package, launches[include.target], indexes) \
            if include.target != include.path else None
        if used is None:
            continue
        declared, known = used
        names = {key for key, _ in include.handed}
        for key, span in include.handed:
            if key not in known and key not in READ_BY_LAUNCH:
                yield _hit(span, key, include.target, _meant(key, declared - names))


def _arguments_used(package: Package, launch: LaunchFile, indexes: dict[str, Index]
                    ) -> tuple[set[str], set[str]] | None:
    """The names an included launch file declares, and every name it declares, reads or
    writes in a string (a Python file) or a word (an XML or YAML file, outside argument
    descriptions); None when some read
    may not show: a Python file not :func:`reads_shown`, a declaration or read with no
    literal name, a file including others (they see every configuration)."""
    if launch.kind == "python":
        index = indexes.get(launch.path)
        return _unread(index) if index is not None and reads_shown(index) else None
    text = without_comments(package.texts.get(launch.path, ""), launch.kind)
    if launch.kind not in ("xml", "yaml") or "include" in text:
        return None
    declared = {name for pattern in FRONTEND_DECLARED for name in pattern.findall(text)}
    return declared, declared | set(_WORD.findall(DESCRIPTION.sub("", text)))  # a word of a
    # description names nothing


_WORD = lazy_pattern(r"[\w.-]+")


def _unread(index: Index) -> tuple[set[str], set[str]] | None:
    """The names the launch file of ``index`` declares, and every name it declares, reads or
    writes in a string; None when a declaration or read has no literal name."""
    found = literal_arguments(index)
    if found is None or not index.calls:
        return None
    module = index.module_of(index.calls[0])
    strings = {node.value for node in nodes_of_class(module, ast.Constant)
               if isinstance(node.value, str)}
    return {name for name in found[1] if name}, strings


def _meant(name: str, declared: set[str]) -> str | None:
    """The declared name ``name`` most likely misspells: one spelled almost the same, else
    one with a word more or less (``params`` for ``params_file``)."""
    close = get_close_matches(name, sorted(declared), n=1, cutoff=0.8)
    if close:
        return close[0]
    worded = sorted(other for other in declared if _a_word_apart(name, other) or
                    _a_word_apart(other, name))
    return worded[0] if len(worded) == 1 else None


def _a_word_apart(short: str, long: str) -> bool:
    return long.startswith(short + "_") or long.endswith("_" + short)


def _hit(span: Span, name: str, included: str, meant: str | None) -> Hit:
    if meant is None:
        return Hit(span, f"`{name}` is handed to `{included}`, which neither declares nor reads "
                         "it: the value is ignored")
    return Hit(span, f"`{name}` is handed to `{included}`, which declares `{meant}` but "
                     f"never uses `{name}`: the value is ignored and `{meant}` is not set",
               f"Hand it as `{meant}`, the name `{included}` declares")
