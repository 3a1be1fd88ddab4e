"""Fixers of launch files: node arguments ROS 2's launch rejects (renamed keywords and
attributes, parameters not in a list), launch actions given arguments they reject, a
misspelt executable, a node started without its package, and an action a stray comma makes
a tuple."""

from __future__ import annotations

import ast
import re
import shlex
from collections.abc import Iterator
from difflib import get_close_matches

from pkgtool.edit.changes import read_source
from pkgtool.edit.core import Edit, EditError, Fix
from pkgtool.edit.pysource import PyDoc
from pkgtool.edit.source import Source
from pkgtool.edit.xml_scan import Element, scan
from pkgtool.findings import Finding
from pkgtool.fix.common import python_nodes, renames
from pkgtool.fix.registry import fixer
from pkgtool.model.package import Package
from pkgtool.rules.launch.invalid_launch_action_argument import (BY_KEYWORD, CMD_BY_KEYWORD,
                                                                 IN_A_LIST, ITEMS)
from pkgtool.rules.launch.invalid_node_argument import (FRONTEND_TAGS, KEYWORDS, REMOVED_KEYWORDS,
                                                        WRONG_ATTRIBUTES, removed_message)
from pkgtool.rules.launch.unknown_substitution import SUBSTITUTION, ros2_substitution
from pkgtool.lazy_regex import lazy_pattern

_ONE_NAME = lazy_pattern(r"`(\w+)`(?: \(.*\))?")
"""What WRONG_ATTRIBUTES says to write when that is one attribute name."""


def _rename(doc: PyDoc, call: ast.Call, keyword: ast.keyword, name: str) -> Fix | None:
    """Rename ``keyword`` of ``call`` to ``name``; None when ``call`` has ``name`` already or
    the keyword is not written where ``ast`` says."""
    old, at = keyword.arg or "", doc.start(keyword)
    if any(k.arg == name for k in call.keywords) or not doc.text.startswith(old, at):
        return None
    return Fix(f"Write `{name}=` instead of `{old}=`",
               (Edit(doc.source.path, at, at + len(old), name),))


def _owners(doc: PyDoc) -> dict[int, ast.Call]:
    """The call each keyword (by id) belongs to."""
    return {id(k): c for c in ast.walk(doc.tree) if isinstance(c, ast.Call) for k in c.keywords}


@fixer("LCH005", "Write the node arguments ROS 2's launch takes")
def node_arguments(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Python node actions: rename ``node_executable=``, ``node_name=`` and
    ``node_namespace=`` (ROS 2 Dashing and Eloquent) to ``executable=``, ``name=`` and
    ``namespace=``, and a keyword the action does not take when exactly one it takes is
    spelled like it (``nam=`` becomes ``name=``); put a ``parameters=`` value that is no list
    into one (``parameters=path`` becomes ``parameters=[path]``, a tuple a list); split a
    string literal given to ``arguments=`` or ``ros_arguments=`` the way a shell does
    (``'--log-level debug'`` becomes ``['--log-level', 'debug']``). XML: rename
    the ROS 1 and Python attributes of ``<node>`` that have one ROS 2 name (``type`` becomes
    ``exec``, ``ns`` ``namespace``). Safe: launch raised or refused the file. A call or tag
    that already has the new name, YAML launch files, remappings, a missing executable and
    ROS 1 attributes with no ROS 2 equivalent need the user."""
    for doc, finding, nodes in python_nodes(package, findings):
        calls = [c for c in ast.walk(doc.tree) if isinstance(c, ast.Call)]
        mine = [c for c in calls if c in nodes or any(k.value in nodes for k in c.keywords)]
        for call in mine:
            fix = _node_fix(doc, call, finding)
            if fix is not None:
                yield fix
    yield from xml_node_attributes(package, [f for f in findings
                                             if f.span.path.endswith(".xml")])


def _node_fix(doc: PyDoc, call: ast.Call, finding: Finding) -> Fix | None:
    """The fix of ``finding`` on the node action ``call``, if it has one."""
    action = ast.unparse(call.func).rpartition(".")[2]
    for keyword in call.keywords:
        name = keyword.arg or ""
        if finding.message in (removed_message(action, name),
                               f"`{action}()` has no `{name}` argument: launch raises "
                               "TypeError"):
            close = get_close_matches(name, sorted(KEYWORDS.get(action, ())), n=2)
            new = REMOVED_KEYWORDS.get(name) or (close[0] if len(close) == 1 else None)
            return _rename(doc, call, keyword, new) if new else None
        if name == "parameters" and finding.message == f"`parameters=` of `{action}()` is " \
                "not a list":
            return _in_a_list(doc, keyword.value)
        if finding.message.startswith(f"`{name}=` of `{action}()` is one string") and \
                isinstance(keyword.value, ast.Constant) and isinstance(keyword.value.value, str):
            try:
                words = shlex.split(keyword.value.value)
            except ValueError:  # an unclosed quote: the user's to split
                return None
            return Fix(f"Split `{name}=` into a list", (Edit(
                doc.source.path, doc.start(keyword.value), doc.end(keyword.value),
                "[" + ", ".join(doc.string(word) for word in words) + "]"),))
    return None


def xml_node_attributes(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Rename the attributes of XML node tags that ROS 2 calls otherwise."""
    for path, source, root in _xml_files(package, findings):
        tags = [e for e in _descendants(root) if e.local in FRONTEND_TAGS]
        written: set[tuple[int, str]] = set()  # two old names of one new one: the first
        for finding in (f for f in findings if f.span.path == path):
            line = source.line_starts[finding.span.line - 1]
            for tag in (t for t in tags  # lxml gives some line of the opening tag
                        if source.line_start(t.start) <= line <= t.inner_start):
                fix = _attribute_fix(source, tag, finding.message)
                if fix is not None and (tag.start, fix.edits[0].replacement) not in written:
                    written.add((tag.start, fix.edits[0].replacement))
                    yield fix


def _xml_files(package: Package, findings: list[Finding]
               ) -> Iterator[tuple[str, Source, Element]]:
    """Each file of ``findings`` that reads and scans as markup, with its root element."""
    for path in sorted({f.span.path for f in findings}):
        try:
            source = read_source(package.root, path)
        except EditError:
            continue
        root = scan(source.text) if source is not None else None
        if source is not None and root is not None:
            yield path, source, root


def _attribute_fix(source: Source, tag: Element, message: str) -> Fix | None:
    for old, instead in WRONG_ATTRIBUTES.items():
        new = _ONE_NAME.fullmatch(instead)
        if message != f"`<{tag.local}>` has no `{old}` attribute in ROS 2" or new is None or \
                new.group(1) in tag.attributes:
            continue
        written = re.search(rf"\s({re.escape(old)})\s*=", source.text[tag.start:tag.inner_start])
        if written:
            at = tag.start + written.start(1)
            return Fix(f"Write `{new.group(1)}` instead of `{old}`",
                       (Edit(source.path, at, at + len(old), new.group(1)),))
    return None


def _descendants(element: Element) -> Iterator[Element]:
    yield element
    for child in element.children:
        yield from _descendants(child)


def _in_a_list(doc: PyDoc, value: ast.expr) -> Fix | None:
    """``value`` as a list: a tuple display with its brackets changed, else in brackets."""
    start, end, path = doc.start(value), doc.end(value), doc.source.path
    if isinstance(value, ast.Tuple):
        if doc.text[start] != "(" or doc.text[end - 1] != ")":
            return None
        return Fix("Write the tuple as a list", (Edit(path, start, start + 1, "["),
                                                 Edit(path, end - 1, end, "]")))
    return Fix("Put the parameters in a list", (Edit(path, start, start, "["),
                                                Edit(path, end, end, "]")))


@fixer("LCH010", "Pass launch actions the arguments they take")
def action_arguments(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """``launch_arguments={...}`` gains ``.items()``; ``LaunchDescription(action)`` gets the
    action in a list; ``DeclareLaunchArgument`` gets its default as ``default_value=``, a
    shortened keyword written out (``default=`` becomes ``default_value=``) and a number or
    bool default as text (``False`` becomes ``'false'``); ``PathJoinSubstitution``'s parts go
    in one list; ``Command(['xacro', path])`` gets its space (``'xacro '``);
    ``ExecuteProcess``'s command written as one string becomes its list of words (when no
    quotes, newlines or comments, and no shell signs without ``shell=True``, make the split
    uncertain), and a command given as the one positional argument is passed as ``cmd=``.
    Safe: each raised TypeError, or ran a command that does not exist."""
    for doc, finding, nodes in python_nodes(package, findings):
        node, path = (nodes[0] if nodes else None), doc.source.path
        if finding.fix == ITEMS and isinstance(node, (ast.Dict, ast.DictComp)):
            yield Fix("Pass the dict's `.items()`", (Edit(path, doc.end(node), doc.end(node),
                                                          ".items()"),))
        elif isinstance(node, ast.Call) and finding.fix == IN_A_LIST.format(
                ast.unparse(node.func).rpartition(".")[2]):
            yield Fix("Put the action in a list", (Edit(path, doc.start(node),
                                                        doc.start(node), "["),
                                                   Edit(path, doc.end(node), doc.end(node), "]")))
        elif isinstance(node, ast.keyword) and finding.fix and node.arg and \
                finding.fix.startswith("Write `") and finding.fix.endswith("=`"):
            fix = _rename(doc, _owners(doc)[id(node)], node, finding.fix[7:-2])
            if fix is not None:
                yield fix
        elif isinstance(node, (ast.Constant, ast.keyword)) and finding.fix and \
                finding.fix.startswith("Write `cmd=[") and finding.fix != CMD_BY_KEYWORD:
            yield Fix("Write the command as a list of words",
                      (Edit(path, doc.start(node), doc.end(node), finding.fix[7:-1]),))
        elif finding.fix == CMD_BY_KEYWORD and isinstance(node, ast.expr):
            yield Fix("Pass the command as `cmd=`",
                      (Edit(path, doc.start(node), doc.start(node), "cmd="),))
        elif isinstance(node, ast.Constant) and finding.fix and \
                finding.fix.startswith("Write `'") and finding.fix.endswith("'`"):
            what = "Add the space after the program" if isinstance(node.value, str) else \
                "Write the default as text"
            yield Fix(what, (Edit(path, doc.start(node), doc.end(node),
                                  doc.string(finding.fix[8:-2])),))
        elif finding.fix == BY_KEYWORD and isinstance(node, ast.expr):
            yield from _by_keyword(doc, node)
        elif finding.fix and finding.fix.startswith("Write `[") and isinstance(node, ast.expr):
            yield from _parts_in_a_list(doc, node)


def _parts_in_a_list(doc: PyDoc, second: ast.expr) -> Iterator[Fix]:
    """``PathJoinSubstitution(a, b, c)`` becomes ``PathJoinSubstitution([a, b, c])``."""
    for call in ast.walk(doc.tree):
        if isinstance(call, ast.Call) and len(call.args) > 1 and call.args[1] is second:
            yield Fix("Put the parts in one list", (
                Edit(doc.source.path, doc.start(call.args[0]), doc.start(call.args[0]), "["),
                Edit(doc.source.path, doc.end(call.args[-1]), doc.end(call.args[-1]), "]")))


def _by_keyword(doc: PyDoc, default: ast.expr) -> Iterator[Fix]:
    """``DeclareLaunchArgument(name, default)`` becomes ``(name, default_value=default)``
    when the default is its last positional argument and no ``default_value=`` is given."""
    for call in ast.walk(doc.tree):
        if isinstance(call, ast.Call) and len(call.args) == 2 and call.args[1] is default and \
                not any(k.arg == "default_value" for k in call.keywords):
            at = doc.start(default)
            yield Fix("Pass the default as `default_value=`",
                      (Edit(doc.source.path, at, at, "default_value="),))


@fixer("LCH001", "Start the executable the misspelt one is close to", safe=False)
def executable(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Rename the executable a launch file starts to the one executable the package installs
    that is spelled like it (``talkr`` to ``talker``). Unsafe: it guesses which executable
    was meant; launching stopped with "executable not found" before."""
    yield from renames(package, findings, re.compile(r"^`([^`]+)` is not an executable"))


@fixer("LCH028", "Hand an included launch file the argument it declares", safe=False)
def include_argument(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Rename a misspelt argument handed to an included launch file of the package to the
    one it declares spelled like it (``use_sim_tme`` to ``use_sim_time``); a name a word
    away (``params`` for ``params_file``) is the user's to choose. Unsafe: the included file
    then gets the value, where it kept its default before."""
    yield from renames(package, findings, re.compile(r"^`([^`]+)` is handed to"),
                       lazy_pattern(r"Hand it as `([^`]+)`, the name `[^`]+` declares"))


@fixer("LCH013", "Name the package of the executable a node starts")
def node_package(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Python node actions: insert ``package='<this package>'`` before the ``executable=``
    that LCH013 reports (``Node(executable='talker')`` becomes ``Node(package='demo',
    executable='talker')``); in XML, add ``pkg="<this package>"`` to the ``<node>`` tag.
    Safe: launch could not find the executable before. YAML launch files need the user."""
    yield from _xml_node_packages(package, [f for f in findings if f.span.path.endswith(".xml")])
    for doc, _, nodes in python_nodes(package, findings):
        owners = _owners(doc)
        keyword = next((k for c in owners.values() for k in c.keywords
                        if k.arg == "executable" and k.value in nodes), None)
        if keyword is not None and doc.text.startswith("executable", doc.start(keyword)):
            text = f"package={doc.string(package.name)}, "
            yield Fix(f"Add `{text[:-2]}`", (Edit(doc.source.path, doc.start(keyword),
                                                  doc.start(keyword), text),))


def _xml_node_packages(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Add ``pkg=`` to each ``<node>`` tag without one that starts on a finding's line."""
    for path, source, root in _xml_files(package, findings):
        lines = {source.line_starts[f.span.line - 1] for f in findings if f.span.path == path}
        for tag in _descendants(root):
            name_end = tag.start + 1 + len(tag.tag)
            if tag.local == "node" and "pkg" not in tag.attributes and \
                    source.line_start(tag.start) in lines and \
                    source.text[tag.start + 1:name_end] == tag.tag:
                yield Fix(f'Add `pkg="{package.name}"`',
                          (Edit(source.path, name_end, name_end, f' pkg="{package.name}"'),))


@fixer("LCH015", "Write the substitution ROS 2's launch has", safe=False)
def substitution_name(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Rename a substitution ROS 2's launch does not have: ROS 1's ``$(find pkg)``, ``$(arg
    x)`` and ``$(optenv X d)`` become ``$(find-pkg-share pkg)``, ``$(var x)`` and ``$(env X
    d)`` (in XML, ``$(optenv X)`` becomes ``$(env X '')``: ``env`` fails on an unset variable
    without a default); a misspelt one the substitution it is close to. Unsafe: a misspelling
    is a guess, and ``find-pkg-share`` is the installed share folder, where ROS 1's ``find``
    was the source folder; the file did not launch at all before."""
    for finding in findings:
        try:
            source = read_source(package.root, finding.span.path)
        except EditError:
            continue
        if source is None or finding.span.line > len(source.line_starts):
            continue
        written = SUBSTITUTION.match(
            source.text, source.line_starts[finding.span.line - 1] + finding.span.col - 1)
        meant = ros2_substitution(written.group(1)) if written else None
        if written is None or meant is None:
            continue
        edits = [Edit(source.path, written.start(1), written.end(1), meant)]
        close = source.text.find(")", written.end())
        if written.group(1) == "optenv" and len(source.text[written.end():close].split()) < 2:
            if not source.path.endswith(".xml") or close < 0:
                continue  # a YAML scalar may be quoted with '
            edits.append(Edit(source.path, close, close, " ''"))
        yield Fix(f"Write `$({meant}` for `$({written.group(1)}`", tuple(edits))


@fixer("LCH016", "Call the LaunchDescription method the misspelt one is close to", safe=False)
def description_method(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Rename an attribute ``LaunchDescription`` lacks to the one it has spelled like it
    (``add_actoin`` to ``add_action``). Unsafe: it guesses which method was meant; the launch
    failed before."""
    yield from renames(package, findings,
                       re.compile(r"^`\w+` is a `LaunchDescription`, which has no `(\w+)`"),
                       before=".")


@fixer("LCH018", "Remove the comma that makes a launch action a tuple")
def action_tuple(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Delete the comma after ``node = Node(...)`` when the name is given to the launch as
    an action. Safe: the launch failed with AttributeError on the tuple."""
    for doc, finding, nodes in python_nodes(package, findings):
        read = next((n for n in nodes if isinstance(n, ast.Name)), None)
        line = _COMMA_LINE.search(finding.fix or "")
        assignment = next((n for n in ast.walk(doc.tree) if read is not None and line and
                           isinstance(n, ast.Assign) and isinstance(n.value, ast.Tuple) and
                           n.value.end_lineno == int(line[1]) and len(n.value.elts) == 1 and
                           isinstance(n.targets[0], ast.Name) and n.targets[0].id == read.id),
                          None)
        if assignment is None:
            continue
        item, whole = assignment.value.elts[0], assignment.value  # type: ignore[attr-defined]
        if doc.text[doc.end(item):doc.end(whole)].strip() == ",":
            yield Fix(f"Remove the comma after `{read.id}`'s action",  # type: ignore[union-attr]
                      (Edit(doc.source.path, doc.end(item), doc.end(whole), ""),))


_COMMA_LINE = lazy_pattern(r"Remove the comma that ends line (\d+)")
"""LCH018's help: the line the tuple's comma ends."""


@fixer("LCH020", "Add the launch argument's action to the returned description")
def argument_added(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Add the name a ``DeclareLaunchArgument`` is assigned to at the start of the list of the
    function's ``return LaunchDescription([...])``, when that is the name's only assignment in
    the function. Safe: the launch failed without the argument, and declaring it is what the
    author wrote the action for. A declaration assigned over (``x = ...`` twice) or a
    description built with ``add_action`` needs the user."""
    for doc, _, nodes in python_nodes(package, findings):
        call = next((n for n in nodes if isinstance(n, ast.Call)), None)
        function = next((f for f in ast.walk(doc.tree) if isinstance(f, ast.FunctionDef) and
                         call is not None and call in ast.walk(f)), None)
        if call is None or function is None:
            continue
        stores = [a for a in ast.walk(function) if isinstance(a, ast.Assign) and
                  len(a.targets) == 1 and isinstance(a.targets[0], ast.Name)]
        mine = next((a for a in stores if a.value is call), None)
        name = mine.targets[0].id if mine is not None else None  # type: ignore[attr-defined]
        listed = _returned_list(function)
        if name is None or listed is None or \
                sum(a.targets[0].id == name for a in stores) != 1:  # type: ignore[attr-defined]
            continue
        at = doc.start(listed) + 1
        yield Fix(f"Add `{name}` to the returned `LaunchDescription`",
                  (Edit(doc.source.path, at, at, f"{name}, " if listed.elts else name),))


def _returned_list(function: ast.FunctionDef) -> ast.List | None:
    """The list literal of the function's one ``return LaunchDescription([...])``."""
    returns = [r for r in ast.walk(function) if isinstance(r, ast.Return)]
    value = returns[0].value if len(returns) == 1 else None
    if isinstance(value, ast.Call) and ast.unparse(value.func).endswith("LaunchDescription") \
            and len(value.args) == 1 and isinstance(value.args[0], ast.List):
        return value.args[0]
    return None


@fixer("LCH030", "Include the launch file with the source that reads every format", safe=False)
def any_source(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Call ``AnyLaunchDescriptionSource`` (imported from ``launch.launch_description_sources``)
    where a launch description source of another format than the included file's is called
    by name; launch then picks the reader by the file's suffix. Unsafe: the include failed
    before, but the import of the class no longer called stays (flake8's F401 in the
    package's linter test until it is removed)."""
    for doc, _, nodes in python_nodes(package, findings):
        call = next((n for n in nodes if isinstance(n, ast.Call) and
                     isinstance(n.func, ast.Name)), None)
        if call is None:
            continue
        func = call.func
        yield Fix("Use `AnyLaunchDescriptionSource`", (
            Edit(doc.source.path, doc.start(func), doc.end(func), "AnyLaunchDescriptionSource"),
            *doc.add_imports([("launch.launch_description_sources",
                               "AnyLaunchDescriptionSource")])), safe=False)
