"""What the rules on Python launch files share: the function's name, the launch classes calls
make (which files they read: :func:`pkgtool.rules.syntax_trees.launch_indexes`)."""

from __future__ import annotations

import ast
import re
from collections.abc import Iterable, Iterator

from pkgtool.knowledge.rosdistro import any_stdlib_module
from pkgtool.lazy_regex import lazy_pattern
from pkgtool.model.ast_nodes import last_name, nodes_of_class, subtree
from pkgtool.model.launch import LaunchFile, is_launch_test, parse_launch
from pkgtool.model.launch_reader import FRONTEND_DECLARED, VARIABLE_READ
from pkgtool.model.memo import per_package
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.model.text_comments import without_comments
from pkgtool.rules.scopes import single_assignments
from pkgtool.rules.syntax_trees import Index, launch_indexes

FUNCTION = "generate_launch_description"
"""The function ``ros2 launch`` calls in a Python launch file."""
_DECLARE = "DeclareLaunchArgument"
_READ = "LaunchConfiguration"


def text_argument(call: ast.Call, keyword: str) -> str | None:
    """The first argument (or ``keyword``) of a call, when it is a string literal (the name a
    ``DeclareLaunchArgument`` declares, a ``LaunchConfiguration`` reads)."""
    value = call.args[0] if call.args else next(
        (k.value for k in call.keywords if k.arg == keyword), None)
    return value.value if isinstance(value, ast.Constant) and isinstance(value.value, str) \
        else None


def within(module: str, homes: tuple[str, ...]) -> bool:
    """True when ``module`` is one of ``homes`` or a submodule of one."""
    return any(module == home or module.startswith(home + ".") for home in homes)


def launch_class(call: ast.Call, index: Index) -> tuple[str, str]:
    """The module and class a call of the module ``index`` describes makes when bound by an
    import (``launch.actions``, ``DeclareLaunchArgument``); ``("", "")`` for any other call."""
    module, _, name = (index.qualified(call.func) or "").rpartition(".")
    return (module, name) if module.split(".")[0] in ("launch", "launch_ros") else ("", "")


_PLAIN_MODULES = frozenset({"launch", "launch_ros", "launch_xml", "launch_yaml",
                            "ament_index_python", "os", "sys", "pathlib", "yaml", "json", "math",
                            "typing", "glob", "xacro", "__future__"})
"""Modules a launch file imports that never read its launch configurations behind its back
(a helper module of the package may: ``make_nodes()`` reading ``LaunchConfiguration('x')``)."""
_PASSED_ON = frozenset({"IncludeLaunchDescription", "OpaqueFunction", "SetLaunchConfiguration",
                        "LaunchConfigurationEquals", "LaunchConfigurationNotEquals"})
"""Launch classes through which a configuration is read without a ``LaunchConfiguration`` of
its name in the file: included files see every configuration, an opaque function reads
``context.launch_configurations``, the conditions take a name."""


READ_BY_LAUNCH = frozenset({"launch-prefix", "launch-prefix-filter", "emulate_tty"})
"""Launch configurations launch itself reads for every process it starts (the prefix of one
given none, whether to emulate a terminal)."""


def literal_arguments(index: Index) -> tuple[list[ast.Call], list[str], list[str]] | None:
    """The module's ``DeclareLaunchArgument`` calls, the names they declare and the names
    its ``LaunchConfiguration`` calls read; None when one of those names is no literal."""
    declared = [call for call in index.calls
                if launch_class(call, index)[1] == "DeclareLaunchArgument"]
    names = [text_argument(call, "name") for call in declared]
    reads = [text_argument(call, "variable_name") for call in index.calls
             if launch_class(call, index)[1] == "LaunchConfiguration"]
    if None in names or None in reads:
        return None
    return declared, names, reads  # type: ignore[return-value]


def reads_shown(index: Index) -> bool:
    """True when every read of a configuration shows in the file: it imports only modules
    of :data:`_PLAIN_MODULES` and the standard library, uses none of :data:`_PASSED_ON`, and
    loads no parameter file with substitutions (``ParameterFile(path, allow_substs=True)``
    reads ``$(var name)`` in the file)."""
    modules = {module.split(".")[0] for module in index.aliases.values()}
    return not modules - _PLAIN_MODULES - any_stdlib_module() and \
        not index.relative and \
        not any(launch_class(call, index)[1] in _PASSED_ON or _substitutes(call)
                for call in index.calls)


def _substitutes(call: ast.Call) -> bool:
    """True for a call given ``allow_substs=`` anything but a literal False."""
    return any(k.arg == "allow_substs" and not (isinstance(k.value, ast.Constant) and
                                                k.value.value is False) for k in call.keywords)


def own_nodes(function: ast.AST, index: Index) -> Iterator[ast.AST]:
    """The nodes of ``function``'s own body (those of a nested function are its own), in
    walk order."""
    return (node for node in subtree(function) if index.enclosing_function(node) is function)


def launch_function_nodes(package: Package
                          ) -> Iterator[tuple[str, Index, dict[str, ast.expr], ast.AST]]:
    """Each node of the own body of each function of the package's Python launch files, with
    the file's path and index and the names the function binds once, to their values
    (:func:`~pkgtool.rules.scopes.single_assignments`)."""
    for path, index in launch_indexes(package):
        for function in index.functions:
            single = single_assignments(function)
            for node in own_nodes(function, index):
                yield path, index, single, node


SUBSTITUTIONS = ("launch.substitutions", "launch_ros.substitutions")
"""The modules whose classes are all substitutions."""


def substitution_made(value: ast.expr, index: Index, single: dict[str, ast.expr]) -> str | None:
    """The substitution class ``value`` makes (directly, or through a name the function binds
    once, to it: ``single``), else None."""
    if isinstance(value, ast.Name) and value.id in single:
        value = single[value.id]
    if not isinstance(value, ast.Call):
        return None
    module, name = launch_class(value, index)
    return name if within(module, SUBSTITUTIONS) and name[:1].isupper() else None


def first_substitution(values: Iterable[ast.expr], index: Index, single: dict[str, ast.expr]
                       ) -> str | None:
    """The class of the first of ``values`` that is a substitution (:func:`substitution_made`),
    else None."""
    return next((made for value in values
                 if (made := substitution_made(value, index, single))), None)


@per_package
def launch_tests(package: Package) -> tuple[LaunchFile, ...]:
    """The package's ``launch_testing`` tests (modules defining ``generate_test_description``)
    read as Python launch files: the nodes they start, the packages they name."""
    return tuple(parse_launch(module.path, text) for module in package.modules
                 if (text := package.texts.get(module.path)) is not None and
                 is_launch_test(module.path, text))


def undeclared_reads(package: Package) -> Iterator[tuple[Span, str, set[str]]]:
    """Each read of a launch configuration that no launch file of the package declares or
    sets, with the names its own file declares: a ``LaunchConfiguration('x')`` with no
    default (nor other keyword) whose name the file quotes nowhere else but as a node's
    parameter name (``SetLaunchConfiguration``, ``launch_arguments``) and whose value is
    used (not bound to a name nothing reads), a ``$(var x)`` whose name the file writes
    nowhere else. None when a Python launch file declares an argument under a name made at
    run time."""
    files = list(launch_indexes(package))
    frontends = [(launch.path, without_comments(text, launch.kind))
                 for launch in package.launch_files
                 if launch.kind in ("xml", "yaml") and launch.problem is None and
                 (text := package.texts.get(launch.path)) is not None]
    declared_anywhere = {name for _, text in frontends for pattern in FRONTEND_DECLARED
                         for name in pattern.findall(text)}
    declarations = [c for _, index in files for c in index.calls
                    if last_name(c.func) == _DECLARE]
    names = [text_argument(c, "name") for c in declarations]
    if None in names:
        return  # a name made at run time (a loop, an f-string) may be any of them
    declared_anywhere.update(name for name in names if name is not None)
    for path, index in files:
        declared = {name for c in index.calls if last_name(c.func) == _DECLARE
                    and (name := text_argument(c, "name")) is not None}
        for call in index.calls:
            name = text_argument(call, "variable_name") if last_name(call.func) == _READ else None
            if name is None or name in declared_anywhere or len(call.args) > 1 or any(
                    k.arg != "variable_name" for k in call.keywords) or \
                    _quoted_elsewhere(name, call, index) or _never_used(call, index):
                continue
            yield Span(path, call.lineno, call.col_offset + 1), name, declared
    for path, text in frontends:
        declared = {name for pattern in FRONTEND_DECLARED for name in pattern.findall(text)}
        code = DESCRIPTION.sub("", text)  # the words of descriptions name nothing
        for read in VARIABLE_READ.finditer(text):
            name = read.group(1)
            if name not in declared_anywhere and len(re.findall(
                    rf"(?<![\w.-]){re.escape(name)}(?![\w.-])", code)) == 1:
                yield Span.of_offset(path, text, read.start()), name, declared


def declaration_holders(index: Index) -> dict[str, str]:
    """The names of a launch file bound to a ``DeclareLaunchArgument('x', ...)`` (``x_arg =
    DeclareLaunchArgument('x')``), with the argument each declares."""
    found: dict[str, str] = {}
    for call in index.calls:
        parent = index.parents.get(id(call))
        name = text_argument(call, "name") if last_name(call.func) == _DECLARE else None
        if name is not None and isinstance(parent, ast.Assign):
            found.update((t.id, name) for t in parent.targets if isinstance(t, ast.Name))
    return found


def _quoted_elsewhere(name: str, call: ast.Call, index: Index) -> bool:
    """True when the file of ``call`` (a read of ``name``) holds the string ``name`` anywhere
    else, but as a node's parameter name (a key of a dict given as ``parameters=``): a
    ``SetLaunchConfiguration``, ``launch_arguments`` or a helper may set the configuration."""
    for node in nodes_of_class(index.module_of(call), ast.Constant):
        parent = index.parents.get(id(node))
        if node.value == name and parent is not call and \
                not (isinstance(parent, ast.keyword) and index.parents.get(id(parent)) is call) \
                and not _parameter_name(node, index):
            return True
    return False


def _parameter_name(node: ast.Constant, index: Index) -> bool:
    """True for a key of a dict display in the list a ``parameters=`` keyword gives."""
    parent = index.parents.get(id(node))
    if not (isinstance(parent, ast.Dict) and any(key is node for key in parent.keys)):
        return False
    holder = index.parents.get(id(parent))
    while isinstance(holder, (ast.List, ast.Tuple)):
        holder = index.parents.get(id(holder))
    return isinstance(holder, ast.keyword) and holder.arg == "parameters"


def _never_used(call: ast.Call, index: Index) -> bool:
    """True when ``call`` is the value of ``name = ...`` and its function (or module) binds
    ``name`` again, or reads it nowhere, after it: a substitution nothing performs raises
    nothing."""
    parent = index.parents.get(id(call))
    if not (isinstance(parent, ast.Assign) and len(parent.targets) == 1 and
            isinstance(parent.targets[0], ast.Name)):
        return False
    scope = index.enclosing_function(call) or index.module_of(call)
    target = parent.targets[0]
    later = sorted(((n.lineno, n.col_offset), isinstance(n.ctx, ast.Load))
                   for n in subtree(scope) if isinstance(n, ast.Name) and n.id == target.id
                   and (n.lineno, n.col_offset) > (target.lineno, target.col_offset))
    return not later or not later[0][1]


DESCRIPTION = lazy_pattern(r"""\bdescription\s*[=:]\s*(?:"[^"]*"|'[^']*'|[^\n,}"']*)""")
"""An argument's description in an XML (``description="..."``) or YAML launch file."""
