"""Python launch files read with ``ast``: the nodes, packages and share files they name.

A small evaluator follows string literals, module- and function-level names assigned once,
concatenation, f-strings, ``os.path.join``, ``pathlib`` ``/``, ``PathJoinSubstitution`` and the
share-folder lookups; a loop or comprehension over texts it knows (``for e in ('talker',
'listener')``) is read once per text. Whatever else it meets (``LaunchConfiguration``,
parameters, other loops) is unknown, and unknown values are never reported.
"""

from __future__ import annotations

import ast
import math
from collections.abc import Callable, Collection, Iterator
from typing import Any

from pkgtool.model.ast_nodes import (child_nodes, descendants, handler_stops, last_name,
                                     nodes_of_class)
from pkgtool.model.launch import (COMMAND_PACKAGES, EXISTENCE_CHECKS, PREFIX_PACKAGES,
                                  PROCESS_PACKAGES, TERMINALS, FileRef, NodeRef, PackageRef)
from pkgtool.model.launch_remaps import not_pairs
from pkgtool.model.launch_scopes import (bindings, import_origins, overwritten_values,
                                         read_only_by, scope_nodes, unread_argument_defaults,
                                         unread_attribute_values, unread_module_values,
                                         unread_values, written_paths)
from pkgtool.model.launch_helpers import package_argument, package_parameters
from pkgtool.model.launch_started import certainly_started
from pkgtool.model.span import Span
from pkgtool.model.static_branches import depends_on_ros_distro, reads_environment
from pkgtool.lazy_regex import lazy_pattern
from pkgtool.records import record, replace

SHARE_LOOKUPS = frozenset({"get_package_share_directory", "get_package_share_path",
                           "FindPackageShare"})
PREFIX_LOOKUPS = frozenset({"get_package_prefix", "FindPackagePrefix", "FindPackage"})
SUBSTITUTIONS = frozenset({"FindPackageShare", "FindPackagePrefix", "FindPackage"})
"""Lookups made only when the action holding them runs (the others run when the file does)."""
NODE_ACTIONS = frozenset({"Node", "LifecycleNode", "ComposableNodeContainer"})
_INERT_ACTIONS = frozenset({"ExecuteProcess", "TimerAction", "GroupAction",
                            "IncludeLaunchDescription", "RegisterEventHandler", "OnProcessExit",
                            "OnProcessStart", "OnExecutionComplete", "OnShutdown"})
"""Launch actions (and event handlers) whose construction does nothing: one assigned to a
name nobody reads never runs, nor do the actions inside it
(``delayed = TimerAction(actions=[rviz])`` left out of the description)."""
PLUGIN_ACTIONS = frozenset({"ComposableNode"})
JOINS = frozenset({"join", "PathJoinSubstitution", "joinpath"})
CONCATENATING = ("LaunchDescriptionSource", "Command")
JOINED_PARTS = ("PythonExpression", "Command")
"""Substitutions whose list of parts launch joins into one text (a path, an expression)."""
PRESENCE_CHECKS = frozenset({"get_packages_with_prefixes", "get_package_prefix",
                             "get_package_share_directory", "get_package_share_path",
                             "has_resource", "get_resource"})
"""ament_index calls a launch file makes to find out whether a package is installed."""
NAME_REMAPS = frozenset({"__node", "__name"})
"""Remapping keys that rename a node."""
_LOOKUPS = frozenset({"get_package_share_directory", "get_package_prefix",
                      "get_package_share_path"})
"""ament_index_python's lookups, which raise PackageNotFoundError for a missing package."""
_BROADER_CATCHES = frozenset({"KeyError", "LookupError", "Exception", "BaseException"})
"""Exception classes a handler of which also catches PackageNotFoundError (a KeyError)."""
_MAX_DEPTH = 40
_MAX_TEXT = 4096
"""Longest string the evaluator builds (doubling concatenations stay bounded)."""


@record
class Share:
    """A package's share folder (``share``) or install prefix, and the text appended to it."""

    package: str
    suffix: str = ""
    share: bool = True

    @property
    def parts(self) -> tuple[str, ...] | None:
        """Path components below the folder; None unless the suffix is a clean ``/a/b``."""
        if self.suffix and not self.suffix.startswith("/"):
            return None
        return _split(self.suffix)


Value = str | Share | tuple | None
"""What an expression evaluates to: a string, a share path, a tuple of values, or unknown."""


def _split(text: str) -> tuple[str, ...] | None:
    parts = tuple(p for p in text.split("/") if p not in ("", "."))
    return None if ".." in parts else parts


_METHODS: dict[type, Callable[[_Reader, Any], None]] = {}
"""The method of ``_Reader`` visiting each node class (``visit_<class>`` or ``generic_visit``)."""


class _Reader(ast.NodeVisitor):
    def __init__(self, path: str, tree: ast.Module, exported: frozenset[str]) -> None:
        self.path = path
        self.scopes = [bindings(scope_nodes(tree.body), None)]
        self.cache: list[dict[str, Value]] = [{}]
        self.nodes: list[NodeRef] = []
        self.packages: list[PackageRef] = []
        self.files: list[FileRef] = []
        self.extended: set[tuple[str, tuple[str, ...]]] = set()  # share paths text is added to
        self.continued: set[int] = set()  # parts of a joined list that later parts continue
        self.refound: set[int] = set()  # FindPackageShare(x) calls whose .find(y) looks up y
        self.origins = import_origins(tree)
        self.optional = 0  # > 0 inside a block that runs only if some package is installed
        self.distro_branches = 0  # > 0 inside a branch of a test on the ROS distribution
        self.unread: set[ast.expr] = unread_attribute_values(tree)  # values never read
        self.unread_paths = unread_module_values(tree, exported) | written_paths(tree) | \
            unread_argument_defaults(tree)  # module-level ones, files the code writes, and
        # defaults of launch arguments nothing reads
        self.dead = 0  # > 0 inside a node action that is never started
        self.never_run: set[int] = {id(v) for v in self.unread if self._inert(v)} | (
            {id(v) for v in self.unread_paths if self._inert(v)}
            if _describes_launch(tree) else set())
        # ids of values that never run: actions nothing starts (``self.x = Node(...)`` never
        # read; in a launch file, a module-level one nothing reads too: a helper module's may
        # be imported from outside the package; a function's, added when it is visited), and
        # what only those read (``cmd = Command([...])`` of such a node)
        self.checked: set[tuple[str, tuple[str, ...]]] | None = set()  # share paths asked
        # whether they exist (None: one the reader cannot work out)
        self.read_names = frozenset(n.id for n in nodes_of_class(tree, ast.Name)
                                    if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Load))
        self.presence_flags = presence_flags(tree)
        self.certain = certainly_started(tree)
        self.package_parameters = package_parameters(tree, SHARE_LOOKUPS | PREFIX_LOOKUPS,
                                                     SUBSTITUTIONS)
        self.eager_helpers = frozenset(name for name, p in self.package_parameters.items()
                                       if not p.substitution)  # may raise: may be checked
        self.declarations = [c for c in nodes_of_class(tree, ast.Call)
                             if last_name(c.func) == "DeclareLaunchArgument"]

    def _span(self, node: ast.AST) -> Span:
        return Span(self.path, getattr(node, "lineno", 1), getattr(node, "col_offset", 0) + 1)

    def visit(self, node: ast.AST) -> None:
        """``ast.NodeVisitor.visit`` with the method of each node class looked up once; what
        is inside a value that never runs is recorded as unused."""
        kind = type(node)
        method = _METHODS.get(kind)
        if method is None:
            method = getattr(_Reader, f"visit_{kind.__name__}", _Reader.generic_visit)
            _METHODS[kind] = method
        never = id(node) in self.never_run
        self.dead += never
        method(self, node)
        self.dead -= never

    def _inert(self, value: ast.expr) -> bool:
        """True for a call making a launch action (or event handler) whose construction does
        nothing: one that nothing starts never runs, nor does what it holds."""
        return isinstance(value, ast.Call) and (
            self._action(value.func) in NODE_ACTIONS | PLUGIN_ACTIONS or
            last_name(value.func) in _INERT_ACTIONS)

    def generic_visit(self, node: ast.AST) -> None:
        """Visit the children as ``ast.NodeVisitor`` does, less the context and operator nodes
        (nothing here visits them): a third fewer visits."""
        for child in child_nodes(node):
            self.visit(child)

    def visit_Constant(self, node: ast.Constant) -> None:
        """Nothing: a constant holds no node (``ast.NodeVisitor``'s method would first look
        for methods of the constant classes deprecated since Python 3.8, an exception each)."""

    # scopes -----------------------------------------------------------------------------
    def visit_FunctionDef(self, node: ast.FunctionDef | ast.AsyncFunctionDef) -> None:
        if len(self.scopes) > 1 and not node.decorator_list and \
                node.name not in self.read_names:
            return  # a nested function nothing calls or passes on (to OpaqueFunction): dead
        for default in (*node.args.defaults, *node.args.kw_defaults, *node.decorator_list):
            if default is not None:
                self.visit(default)
        nodes = scope_nodes(node.body)
        self.scopes.append(bindings(nodes, node.args))
        self.cache.append({})
        unread = unread_values(node, nodes) | overwritten_values(node, nodes)
        dead = {call for call in unread if self._inert(call)}
        fed = read_only_by(node, nodes, dead) if dead else set()
        self.unread.update(unread, fed)
        self.never_run.update(id(value) for value in (*dead, *fed))
        for statement in node.body:
            self.visit(statement)
        self.scopes.pop()
        self.cache.pop()

    visit_AsyncFunctionDef = visit_FunctionDef

    # loops over literal names -----------------------------------------------------------
    def visit_ListComp(self, node: ast.ListComp | ast.GeneratorExp | ast.SetComp) -> None:
        """``[Node(executable=e) for e in ('talker', 'listener')]``: the element once for each
        text of a literal (or a name bound once to one), the loop name bound to it."""
        generator = node.generators[0] if len(node.generators) == 1 else None
        if generator is None or generator.ifs:
            self.generic_visit(node)
            return
        self._each(generator.target, generator.iter, [node.elt], lambda: self.generic_visit(node))

    visit_GeneratorExp = visit_SetComp = visit_ListComp

    def visit_For(self, node: ast.For) -> None:
        """``for e in ('talker', 'listener'): ld.add_action(Node(executable=e))``: the body
        once for each text, as for a comprehension."""
        if node.orelse:
            self.generic_visit(node)
            return
        self._each(node.target, node.iter, node.body, lambda: self.generic_visit(node))

    def _each(self, target: ast.expr, iterable: ast.expr, body: list[Any],
              otherwise: Callable[[], None]) -> None:
        """Visit ``body`` once per text ``iterable`` certainly holds, ``target`` (a name)
        bound to it; else ``otherwise()`` (the loop read as any other code)."""
        items = self.value(iterable) if isinstance(target, ast.Name) else None
        if not (isinstance(items, tuple) and items and
                all(isinstance(item, str) for item in items)):
            otherwise()
            return
        self.visit(iterable)
        for item in items:
            bound = ast.copy_location(ast.Constant(item), target)
            self.scopes.append({target.id: bound})  # type: ignore[attr-defined]
            self.cache.append({})
            for part in body:
                self.visit(part)
            self.scopes.pop()
            self.cache.pop()

    # blocks that run only when a package is installed ------------------------------------
    def visit_If(self, node: ast.If) -> None:
        self.visit(node.test)
        checked = any(isinstance(n, ast.Call) and last_name(n.func) in PRESENCE_CHECKS or
                      isinstance(n, ast.Name) and n.id in self.presence_flags or
                      reads_environment(n, "RMW_IMPLEMENTATION")  # installed when selected
                      for n in descendants(node.test))
        distro = depends_on_ros_distro(node.test, self._assigned)
        self.distro_branches += distro
        self._visit_block(node.body, checked)
        self._visit_block(node.orelse, False)
        self.distro_branches -= distro

    def _assigned(self, name: str) -> ast.expr | None:
        """The one expression ``name`` is assigned in the innermost scope binding it."""
        return next((scope[name] for scope in reversed(self.scopes) if name in scope), None)

    def _resolved(self, node: ast.expr | None) -> ast.expr | None:
        """``node``, or for a name the expression it is assigned, followed through names;
        None when a name's value is not known (or more than ``_MAX_DEPTH`` names are chained)."""
        for _ in range(_MAX_DEPTH + 1):
            if not isinstance(node, ast.Name):
                return node
            node = self._assigned(node.id)
        return None

    def visit_Try(self, node: ast.Try) -> None:
        self._visit_block(node.body, _checks_presence(node, self.eager_helpers))
        for part in (*node.handlers, *node.orelse, *node.finalbody):
            self.visit(part)

    def _visit_block(self, body: list[ast.stmt], optional: bool) -> None:
        self.optional += optional
        for statement in body:
            self.visit(statement)
        self.optional -= optional

    def _function_name(self, func: ast.expr) -> str:
        """The name a call's function ends in, through an import's alias
        (``get_package_share_directory as pkgdir``: ``pkgdir(...)`` is the lookup)."""
        imported = {o.rsplit(".", 1)[-1] for o in self.origins.get(func.id, ())} \
            if isinstance(func, ast.Name) else set()
        return imported.pop() if len(imported) == 1 else last_name(func)

    def _action(self, func: ast.expr) -> str:
        """The launch action a call constructs, through the file's imports ('' for none).

        ``Node`` imported from rclpy is not one; ``LaunchNode`` imported as launch_ros's
        ``Node`` is. A name the file never imports (a star import) keeps the benefit of the
        doubt.
        """
        base = func
        while isinstance(base, ast.Attribute):
            base = base.value
        origins = self.origins.get(base.id) if isinstance(base, ast.Name) else None
        if not origins:
            return last_name(func)
        launch = sorted(o for o in origins if o.split(".")[0] == "launch_ros")
        if not launch:
            return ""
        return launch[0].rsplit(".", 1)[-1] if isinstance(func, ast.Name) else last_name(func)

    # evaluation -------------------------------------------------------------------------
    def value(self, node: ast.expr | None, depth: int = 0, top: int | None = None) -> Value:
        if node is None or depth > _MAX_DEPTH:
            return None
        if isinstance(node, ast.Constant):
            return node.value if isinstance(node.value, str) else None
        if isinstance(node, ast.Name):
            return self._name_value(node.id, depth, top)
        if isinstance(node, (ast.List, ast.Tuple)):
            return tuple(self.value(e, depth + 1, top) for e in node.elts)
        if isinstance(node, ast.JoinedStr):
            return _concat([None if isinstance(v, ast.FormattedValue) and v.format_spec else
                            self.value(v.value if isinstance(v, ast.FormattedValue) else v,
                                       depth + 1, top) for v in node.values])
        if isinstance(node, ast.BinOp):
            left = self.value(node.left, depth + 1, top)
            right = self.value(node.right, depth + 1, top)
            if isinstance(node.op, ast.Add):
                return _concat([left, right])
            return _join([left, right]) if isinstance(node.op, ast.Div) else None
        if isinstance(node, ast.Call):
            return self._call_value(node, depth, top)
        return None

    def _name_value(self, name: str, depth: int, top: int | None) -> Value:
        """A name's value in the innermost scope binding it (each evaluated once per scope)."""
        last = len(self.scopes) - 1 if top is None else top
        for level in range(last, -1, -1):
            if name in self.scopes[level]:
                cache = self.cache[level]
                if name not in cache:
                    cache[name] = None  # a name defined through itself stays unknown
                    cache[name] = self.value(self.scopes[level][name], depth + 1, level)
                return cache[name]
        return None

    def _call_value(self, node: ast.Call, depth: int, top: int | None) -> Value:
        name = self._function_name(node.func)
        first = node.args[0] if node.args else None
        if name in SHARE_LOOKUPS or name in PREFIX_LOOKUPS:
            package = self.value(_keyword(node, "package") or first, depth + 1, top)
            return Share(package, "", name in SHARE_LOOKUPS) if isinstance(package, str) else None
        if name == "find" and _find_of_a_lookup(node):
            # FindPackageShare('pkg').find('pkg'): the folder, found when the line runs
            looked_up = self.value(first or node.func.value, depth + 1, top)
            if isinstance(looked_up, Share):
                return looked_up
            return Share(looked_up, "", last_name(node.func.value.func) == "FindPackageShare") \
                if isinstance(looked_up, str) else None
        if name in JOINS:
            items = [self.value(a, depth + 1, top) for a in node.args]
            if isinstance(node.func, ast.Attribute) and name == "joinpath":
                items.insert(0, self.value(node.func.value, depth + 1, top))
            if name == "PathJoinSubstitution" and len(items) == 1 and isinstance(items[0], tuple):
                items = list(items[0])
            return _join(items)
        if name in ("Path", "PurePath", "str", "TextSubstitution") and len(node.args) == 1:
            return self.value(first, depth + 1, top)
        if name.endswith(CONCATENATING) and first is not None:
            inner = self.value(first, depth + 1, top)
            return _concat(list(inner)) if isinstance(inner, tuple) else inner
        return None

    # recording --------------------------------------------------------------------------
    def visit_Call(self, node: ast.Call) -> None:
        if last_name(node.func) in EXISTENCE_CHECKS:
            self._record_check(node)
        self._record_call(node)
        parts = node.args[0] if node.args and last_name(node.func).endswith(JOINED_PARTS) else None
        items = parts.elts if isinstance(parts, (ast.List, ast.Tuple)) else []
        for part, after in zip(items, items[1:]):
            if not (isinstance(after, ast.Constant) and isinstance(after.value, str) and
                    after.value[:1].isspace()):  # the next part goes on with its text
                self.continued.update(id(n) for n in ast.walk(part))
        self.generic_visit(node)

    def _record_check(self, node: ast.Call) -> None:
        """Note the share path ``os.path.exists(path)`` or ``Path(path).exists()`` asks about."""
        func = node.func
        asked = node.args[0] if node.args else \
            func.value if isinstance(func, ast.Attribute) else None
        if isinstance(asked, ast.Call) and last_name(asked.func) in ("Path", "PurePath") and \
                asked.args:
            asked = asked.args[0]
        found = self.value(asked) if asked is not None else None
        if isinstance(found, Share) and found.share and found.parts is not None:
            if self.checked is not None:
                self.checked.add((found.package, found.parts))
        elif not isinstance(found, str):
            self.checked = None  # a path not worked out: any of the file's may be the one

    def _record_call(self, node: ast.Call) -> None:
        name, action = self._function_name(node.func), self._action(node.func)
        if action in NODE_ACTIONS or action in PLUGIN_ACTIONS:
            package_node = _keyword(node, "package")
            executable_node = None if action in PLUGIN_ACTIONS else (
                _keyword(node, "executable") or _keyword(node, "node_executable"))
            package, executable = self.value(package_node), self.value(executable_node)
            arguments = tuple(k.arg or "**" for k in node.keywords)
            if any(isinstance(a, ast.Starred) for a in node.args):
                arguments += ("*",)
            parameters = _keyword(node, "parameters")
            files, other = self._parameter_files(parameters)
            name, unknown = self._node_name(node)
            namespace = self.value(_keyword(node, "namespace"))
            output = self.value(_keyword(node, "output"))
            not_text = next(((self._span(literal), keyword) for keyword in _TEXT_LISTS
                             for literal in _non_text(_keyword(node, keyword))), None)
            remaps = not_pairs(_keyword(node, "remappings"), self._resolved)
            text_not_list = next(((self._span(given), keyword) for keyword in _ARGUMENT_LISTS
                                  if (given := _keyword(node, keyword)) is not None and
                                  self._is_text(given)), None)
            shell = _keyword(node, "shell")
            joined = None if shell is not None and not (isinstance(shell, ast.Constant) and
                                                        shell.value is False) else \
                next(((self._span(item), keyword, item.value) for keyword in _ARGUMENT_LISTS
                      for item in _joined_words(_keyword(node, keyword),
                                                keyword == "ros_arguments")), None)
            self.nodes.append(NodeRef(
                package if isinstance(package, str) else None,
                executable if isinstance(executable, str) else None, self._span(node), action,
                arguments,
                package_node and self._span(package_node),
                executable_node and self._span(executable_node), bool(self.optional),
                files, other_distros=bool(self.distro_branches), name=name,
                namespace=namespace if isinstance(namespace, str) else None,
                name_unknown=unknown or "**" in arguments or "*" in arguments,
                other_parameters=other or "**" in arguments,
                parameters_not_list=self._span(parameters) if self._not_a_list(parameters)
                else None, unused=bool(self.dead),
                remappings_not_pairs=remaps and self._span(remaps),
                inline_parameters=(*self._inline_parameters(parameters),
                                   *self._argument_parameters(node)),
                output=output if isinstance(output, str) else None, not_text=not_text,
                text_not_list=text_not_list, joined_words=joined,
                remapped=tuple(self._remapped(_keyword(node, "remappings"))),
                always_started=node in self.certain))
        elif name == "ExecuteProcess":
            self._ros2_run(node)
        if (action in NODE_ACTIONS or name == "ExecuteProcess") and \
                _keyword(node, "condition") is None:  # a debugging option: the user's tool
            program = program_of(self.value(_keyword(node, "prefix")))
            if name == "ExecuteProcess" and program is None:
                program = program_of(self.value(_keyword(node, "cmd")))
            if program in PREFIX_PACKAGES:
                self.packages.append(PackageRef(PREFIX_PACKAGES[program], self._span(node),
                                                bool(self.optional), bool(self.dead)))
        runs = self._command_executable(node) if name == "Command" else None
        if runs in COMMAND_PACKAGES:
            self.packages.append(PackageRef(COMMAND_PACKAGES[runs], self._span(node),
                                            bool(self.optional), bool(self.dead)))
        if name in ("ExecutableInPackage", "MoveItConfigsBuilder"):  # looked up in the index
            package = self._indexed_package(node, name)
            if isinstance(package, str) and package:
                self.packages.append(PackageRef(package, self._span(node), bool(self.optional),
                                                bool(self.dead)))
        helper = self.package_parameters.get(node.func.id) \
            if isinstance(node.func, ast.Name) else None
        given = package_argument(node, helper) if helper is not None else None
        package = self.value(given) if given is not None else None
        if isinstance(package, str) and package and helper is not None:  # load_yaml('x', ...)
            self.packages.append(PackageRef(package, self._span(node), bool(self.optional),
                                            bool(self.dead) and helper.substitution))
        if _refinding(node):  # FindPackageShare(x).find(y): y is looked up, x never
            self.refound.add(id(node.func.value))  # type: ignore[attr-defined]
        if name in SHARE_LOOKUPS or name in PREFIX_LOOKUPS or _refinding(node):
            found = self.value(node)
            if isinstance(found, Share) and id(node) not in self.refound:
                self.packages.append(PackageRef(found.package, self._span(node),
                                                bool(self.optional),
                                                bool(self.dead) and name in SUBSTITUTIONS))
        self._record_path(node)

    def _indexed_package(self, node: ast.Call, name: str) -> Value:
        """The package ``ExecutableInPackage(executable, package)`` or
        ``MoveItConfigsBuilder(robot, description, package_name)`` finds in the ament index (the
        builder's default: ``<robot>_moveit_config``), when written out."""
        if name == "ExecutableInPackage":
            return self.value(_keyword(node, "package") or
                              (node.args[1] if len(node.args) > 1 else None))
        given = _keyword(node, "package_name") or (node.args[2] if len(node.args) > 2 else None)
        if given is not None:
            return self.value(given)
        robot = self.value(_keyword(node, "robot_name") or (node.args[0] if node.args else None))
        return f"{robot}_moveit_config" if isinstance(robot, str) and robot else None

    def _command_executable(self, node: ast.Call) -> str | None:
        """The executable a ``Command`` substitution runs, when written out: the first word of
        ``Command(['xacro ', path])``, ``Command('xacro ' + path)``, ``Command(f'xacro
        {path}')`` or ``Command([FindExecutable(name='xacro'), ' ', path])`` (also inside a
        one-part ``PathJoinSubstitution``)."""
        first = node.args[0] if node.args else _keyword(node, "command")
        if isinstance(first, (ast.List, ast.Tuple)):
            first = first.elts[0] if first.elts else None
        while isinstance(first, ast.BinOp):
            first = first.left
        if isinstance(first, ast.JoinedStr):
            first = first.values[0] if first.values else None
        if isinstance(first, ast.Call) and last_name(first.func) == "PathJoinSubstitution" and \
                first.args and isinstance(first.args[0], (ast.List, ast.Tuple)) and \
                len(first.args[0].elts) == 1:  # PathJoinSubstitution([FindExecutable(...)])
            first = first.args[0].elts[0]
        if isinstance(first, ast.Call) and last_name(first.func) == "FindExecutable":
            first = _keyword(first, "name") or (first.args[0] if first.args else None)
        found = self.value(first) if isinstance(first, ast.expr) else None
        words = found.split() if isinstance(found, str) else []
        return words[0] if words else None

    def _parameter_files(self, node: ast.expr | None) -> tuple[tuple[FileRef, ...], bool]:
        """The share files among a node's ``parameters=[...]``, and whether anything else
        than those and dicts is given (a launch argument, a value not read statically)."""
        items = node.elts if isinstance(node, (ast.List, ast.Tuple)) else [node] if node else []
        found: list[FileRef] = []
        other = False
        for item in items:
            if self._is_dict(item):
                continue
            default = self._argument_default(item)
            if default is not None:  # a launch argument: its default, or any file given
                item, other = default, True
            value = self.value(item)
            for part in value if isinstance(value, tuple) else (value,):
                if isinstance(part, Share) and part.share and part.parts:
                    found.append(FileRef(part.package, part.parts, self._span(_last_part(item))))
                else:
                    other = True
        return tuple(found), other

    def _argument_default(self, node: ast.expr) -> ast.expr | None:
        """The default value of the launch argument ``LaunchConfiguration('x')`` reads (its
        ``default=``, else that of the file's one ``DeclareLaunchArgument('x', ...)``)."""
        call = self._resolved(node)
        if not isinstance(call, ast.Call) or last_name(call.func) != "LaunchConfiguration" or \
                not call.args or not isinstance(call.args[0], ast.Constant):
            return None
        given = _keyword(call, "default")
        if given is not None:
            return given
        defaults = [_keyword(c, "default_value") for c in self.declarations
                    if _declared_name(c) == call.args[0].value]
        return defaults[0] if len(defaults) == 1 else None

    def _inline_parameters(self, node: ast.expr | None, prefix: str = ""
                           ) -> Iterator[tuple[str, Span, str | None]]:
        """The literal names the dict displays among ``parameters=[...]`` (or ``node``, a
        dict, when ``prefix`` is given) set, with where each is written and the value's
        source when it is a literal."""
        items = [node] if prefix else node.elts if isinstance(node, (ast.List, ast.Tuple)) \
            else []
        for item in items:
            found = self._resolved(item)
            for key, value in zip(*((found.keys, found.values) if isinstance(found, ast.Dict)
                                    else ((), ()))):
                if isinstance(key, ast.Constant) and isinstance(key.value, str):
                    if isinstance(value, ast.Dict):
                        yield from self._inline_parameters(value, f"{prefix}{key.value}.")
                    else:
                        yield f"{prefix}{key.value}", self._span(key), _literal(value)

    def _remapped(self, node: ast.expr | None) -> Iterator[tuple[str, Span]]:
        """The literal names a ``remappings=[(from, to), ...]`` display remaps, where each is
        written."""
        given = self._resolved(node)
        for pair in given.elts if isinstance(given, (ast.List, ast.Tuple)) else ():
            pair = self._resolved(pair)
            if isinstance(pair, (ast.Tuple, ast.List)) and len(pair.elts) == 2 and \
                    isinstance(pair.elts[0], ast.Constant) and isinstance(pair.elts[0].value, str):
                yield pair.elts[0].value, self._span(pair.elts[0])

    def _argument_parameters(self, node: ast.Call) -> Iterator[tuple[str, Span, str | None]]:
        """The ``-p name:=value`` (``--param``) pairs written as literals in ``ros_arguments=``
        and, after ``--ros-args`` (until ``--``), in ``arguments=``: each name, where its pair
        is written, and the source of the value rcl reads from it. Pairs for one node of
        several (``talker:period:=1.0``) are left out."""
        for keyword in ("ros_arguments", "arguments"):
            given = self._resolved(_keyword(node, keyword))
            ros, flag = keyword == "ros_arguments", False
            for item in given.elts if isinstance(given, (ast.List, ast.Tuple)) else ():
                text = item.value if isinstance(item, ast.Constant) and \
                    isinstance(item.value, str) else None
                name, sep, value = (text or "").partition(":=")
                if ros and flag and sep and name and ":" not in name:
                    yield name, self._span(item), _ros_argument_value(value)
                if keyword == "arguments" and text in ("--ros-args", "--"):
                    ros = text == "--ros-args"
                flag = ros and text in ("-p", "--param")

    def _is_text(self, node: ast.expr) -> bool:
        """True when ``node`` is certainly one string: a literal or f-string, also through a
        name assigned one."""
        node = self._resolved(node)
        return isinstance(node, ast.JoinedStr) or \
            isinstance(node, ast.Constant) and isinstance(node.value, str)

    def _not_a_list(self, node: ast.expr | None) -> bool:
        """True when ``node`` is certainly no list: a tuple, dict or set display, a string or
        number, or a call that gives a path or a string (``PathJoinSubstitution([...])``); also
        through a name assigned one of those."""
        node = self._resolved(node)
        if isinstance(node, (ast.Tuple, ast.Dict, ast.DictComp, ast.Set, ast.SetComp,
                             ast.JoinedStr)):
            return True
        if isinstance(node, ast.Constant):
            return node.value is not None
        return isinstance(node, ast.Call) and isinstance(self.value(node), (str, Share))

    def _is_dict(self, node: ast.expr) -> bool:
        """True for a dict display, or a name assigned one."""
        return isinstance(self._resolved(node), (ast.Dict, ast.DictComp))

    def _node_name(self, node: ast.Call) -> tuple[str | None, bool]:
        """The static node name (``name=``, a ``__node`` remapping), and whether a name is
        given that is not read statically."""
        given = _keyword(node, "name") or _keyword(node, "node_name")
        value = self.value(given) if given is not None else None
        names = [value if isinstance(value, str) else None] if given is not None else []
        remaps = _keyword(node, "remappings")
        for pair in _items(self.value(remaps)) if remaps is not None else ():
            if not isinstance(pair, tuple) or not pair or not isinstance(pair[0], str):
                names.append(None)
            elif pair[0] in NAME_REMAPS:
                names.append(pair[1] if len(pair) == 2 and isinstance(pair[1], str) else None)
        for keyword in ("arguments", "ros_arguments"):
            given_arguments = _keyword(node, keyword)
            if given_arguments is not None:
                names.extend(_remapped_names(_items(self.value(given_arguments))))
        known = [n for n in names if n is not None]
        return (known[-1] if known else None), None in names

    def _ros2_run(self, node: ast.Call) -> None:
        """``ros2 run <package> <executable>`` runs a node; ``ros2 launch <package> <file>``
        looks the package up (its share folder); also after a terminal that runs the rest
        (``['gnome-terminal', '--', 'ros2', 'run', ...]``); a program of
        :data:`~pkgtool.model.launch.PROCESS_PACKAGES` (``['rviz2', '-d', config]``) needs
        its package."""
        whole = self.value(_keyword(node, "cmd"))
        if isinstance(whole, tuple):
            whole = tuple(word for part in whole for word in _shell_words(part))
        start = next((i for i, word in enumerate(whole) if word == "ros2"), None) \
            if isinstance(whole, tuple) else None
        command = whole[start:] if start is not None else ()
        if command[:2] == ("ros2", "run"):
            command = _without_prefix(command)
        if (len(command) >= 4 and command[:2] == ("ros2", "run")
                and all(_plain_word(c) for c in command[2:4])):
            self.nodes.append(NodeRef(command[2], command[3], self._span(node),
                                      arguments=("prefix",) if start and any(
                                          w in TERMINALS for w in whole[:start]) else (),
                                      optional=bool(self.optional), name_unknown=True,
                                      other_parameters=True, unused=bool(self.dead)))
        elif (len(command) >= 4 and command[:2] == ("ros2", "launch") and
              isinstance(command[2], str) and
              not command[2].startswith("-") and not {"/", ".", "$"} & set(command[2]) and
              isinstance(command[3], str)):  # a package name: not a launch file's path
            self.packages.append(PackageRef(command[2], self._span(node), bool(self.optional),
                                            bool(self.dead)))
        elif isinstance(whole, tuple) and whole and whole[0] in PROCESS_PACKAGES:
            self.packages.append(PackageRef(PROCESS_PACKAGES[whole[0]], self._span(node),
                                            bool(self.optional), bool(self.dead)))

    def visit_BinOp(self, node: ast.BinOp) -> None:
        self._record_path(node)
        if isinstance(node.op, ast.Add):
            self._record_extended(node.left)
        self.generic_visit(node)

    def visit_JoinedStr(self, node: ast.JoinedStr) -> None:
        self._record_path(node)
        if node.values and isinstance(node.values[0], ast.FormattedValue):
            self._record_extended(node.values[0].value)
        self.generic_visit(node)

    def _record_extended(self, node: ast.expr) -> None:
        """Remember a share path the code appends text to (``base + '_stereo.yaml'``)."""
        found = self.value(node)
        if isinstance(found, Share) and found.share and found.parts:
            self.extended.add((found.package, found.parts))

    def _record_path(self, node: ast.expr) -> None:
        """Record the share file ``node`` names, unless nothing ever uses the path: it is the
        value of a local name never read, or inside a node action never started; nor a path
        that later parts of a ``PythonExpression`` or ``Command`` list continue."""
        if node in self.unread or node in self.unread_paths:
            self.unread_paths.update(descendants(node))  # its parts (``share / 'sdf'``) too
            return
        if self.dead or id(node) in self.continued:
            return
        found = self.value(node)
        if isinstance(found, Share) and found.share and found.parts:
            self.files.append(FileRef(found.package, found.parts, self._span(_last_part(node))))


def _ros_argument_value(text: str) -> str | None:
    """The source of the value rcl makes of the ``value`` of a ``-p name:=value`` argument,
    which it reads as YAML (``1`` an int, ``1.0`` a float, ``true`` a bool, ``[1, 2]`` a
    list, ``fast`` a string); None when that is no scalar or list of scalars."""
    import yaml

    try:
        value = yaml.safe_load(text)
    except yaml.YAMLError:
        return None
    scalars = (bool, int, float, str)
    if isinstance(value, scalars) or isinstance(value, list) and value and \
            all(isinstance(v, scalars) for v in value):
        return None if isinstance(value, float) and not math.isfinite(value) else repr(value)
    return None


def _literal(node: ast.expr) -> str | None:
    """The source of a literal value (``1.0``, ``'a'``, ``[1, 2]``), None for anything else."""
    try:
        ast.literal_eval(node)
    except (ValueError, TypeError, SyntaxError, MemoryError, RecursionError):
        return None
    return ast.unparse(node)


def program_of(value: Value) -> str | None:
    """The program a prefix or command line starts (``'xterm -e'``, ``['/usr/bin/xterm',
    '-e', ...]``): its first word's file name, when that is known."""
    first = value[0] if isinstance(value, tuple) and value else value
    words = first.split() if isinstance(first, str) else []
    return words[0].rpartition("/")[2] if words else None


def _declared_name(call: ast.Call) -> object:
    """The literal name a ``DeclareLaunchArgument(...)`` call declares, or None."""
    name = call.args[0] if call.args else _keyword(call, "name")
    return name.value if isinstance(name, ast.Constant) else None


def _last_part(node: ast.expr) -> ast.expr:
    """Where a path expression names its file: the last part joined or appended."""
    if isinstance(node, ast.BinOp):
        return _last_part(node.right)
    if isinstance(node, (ast.List, ast.Tuple)) and node.elts:
        return _last_part(node.elts[-1])
    if isinstance(node, ast.Call) and node.args:
        name = last_name(node.func)
        if name in JOINS:
            return _last_part(node.args[-1])
        if name.endswith(CONCATENATING) or name in ("Path", "PurePath", "str"):
            return _last_part(node.args[0])
    return node


def _items(value: Value) -> tuple[Value, ...]:
    """The items of a list value; a single unknown item when the list itself is unknown."""
    return value if isinstance(value, tuple) else (value,)


def _remapped_names(arguments: tuple[Value, ...]) -> list[str | None]:
    """Node names a ``__node:=name`` argument sets; None for an argument not read
    statically (it may set one)."""
    found: list[str | None] = []
    for argument in arguments:
        if not isinstance(argument, str):
            found.append(None)
        else:
            found.extend(remapped_name(word) for word in argument.split()
                         if remapped_name(word) is not None)
    return found


def remapped_name(argument: str) -> str | None:
    """The node name of a ``__node:=name`` (or ``__name:=``) argument, else None."""
    key, sep, name = argument.partition(":=")
    return name if sep and key in NAME_REMAPS else None


_SHELL_LINE = lazy_pattern(r"\bros2\s+(?:run|launch)\s")
"""A command line in one string (``'ros2 run pkg exe'`` after ``xterm -e`` or ``bash -c``)."""
_SHELL_SEPARATORS = lazy_pattern(r"[;&|]+")


def _shell_words(part: object) -> tuple[object, ...]:
    """The words of one element of a command list: a string holding a whole ``ros2 run``
    or ``ros2 launch`` command line that a terminal or shell runs, split as a shell splits it
    (quotes kept together) and at ``;``, ``&`` and ``|``; any other element (and a string a
    shell cannot split: an unclosed quote) as it is."""
    if isinstance(part, str) and _SHELL_LINE.search(part):
        import shlex  # only here: most launch files run no shell line

        try:
            words = shlex.split(_SHELL_SEPARATORS.sub(" ; ", part))
        except ValueError:
            return (part,)
        return tuple(word for word in words if word != ";")
    return (part,)


def _without_prefix(command: tuple[object, ...]) -> tuple[object, ...]:
    """``ros2 run`` without its ``--prefix PREFIX`` (or ``--prefix=PREFIX``) option, which
    comes before the package."""
    if command[2:3] == ("--prefix",):
        return command[:2] + command[4:]
    if isinstance(command[2] if len(command) > 2 else None, str) and \
            str(command[2]).startswith("--prefix="):
        return command[:2] + command[3:]
    return command


def _plain_word(word: object) -> bool:
    """True for a word that names itself: no option (``-x``), and nothing a shell expands
    (``$EXE``, ``${EXE:-talker}``, a backquote)."""
    return isinstance(word, str) and bool(word) and not word.startswith("-") and \
        not {"$", "`"} & set(word)


def _keyword(node: ast.Call, name: str) -> ast.expr | None:
    return next((k.value for k in node.keywords if k.arg == name), None)


def _concat(items: list[Value]) -> Value:
    """String concatenation: strings stay strings; a share path may be followed by '/...',
    not by white space (``path + "\\n"`` joins a list of paths, ``path + ' arg:=1'`` a command
    line: text, no file name)."""
    if not items or any(i is None or isinstance(i, tuple) for i in items):
        return None
    head, rest = items[0], items[1:]
    if any(isinstance(i, Share) for i in rest):
        return None
    tail = "".join(str(i) for i in rest)
    if isinstance(head, Share) and any(character.isspace() for character in tail):
        return None
    if len(tail) + len(head.suffix if isinstance(head, Share) else str(head)) > _MAX_TEXT:
        return None
    if isinstance(head, Share):
        return Share(head.package, head.suffix + tail, head.share)
    return str(head) + tail


def _describes_launch(tree: ast.Module) -> bool:
    """True for a module defining ``generate_launch_description`` at its top level."""
    return any(isinstance(s, ast.FunctionDef) and s.name == "generate_launch_description"
               for s in tree.body)


def _join(items: list[Value]) -> Value:
    """``os.path.join`` semantics over a share path and strings (an absolute part: unknown)."""
    if not items or not isinstance(items[0], Share):
        return None
    head = items[0]
    suffix = head.suffix
    for item in items[1:]:
        if not isinstance(item, str) or item.startswith("/"):
            return None
        suffix = f"{suffix.rstrip('/')}/{item}"
    return Share(head.package, suffix, head.share)


def _extends(longer: FileRef, prefix: FileRef, appended_to: bool) -> bool:
    """True when ``longer`` names a file inside the folder ``prefix``, or (``appended_to``:
    the code adds text to ``prefix``) a name built from it; such a prefix is no file itself."""
    whole, start = "/".join(longer.parts), "/".join(prefix.parts)
    return longer.package == prefix.package and whole != start and (
        whole.startswith(start + "/") or (appended_to and whole.startswith(start)))


def _checks_presence(node: ast.Try, helpers: Collection[str] = ()) -> bool:
    """True for a ``try`` whose handlers expect a missing package: one catching
    PackageNotFoundError by name (going on, or stopping with the author's own message when
    it was the last of several alternatives), or around a lookup (or a call of one of the
    file's ``helpers`` making one) anything broader without raising again."""
    looked_up = any(isinstance(n, ast.Call) and (last_name(n.func) in _LOOKUPS or
                                                 isinstance(n.func, ast.Name) and
                                                 n.func.id in helpers)
                    for statement in node.body for n in descendants(statement))
    going_on = [h for h in node.handlers if not handler_stops(h)]  # not re-raising
    return any(isinstance(n, (ast.Name, ast.Attribute)) and
               last_name(n) == "PackageNotFoundError"
               for handler in node.handlers if handler.type and not _raises_again(handler)
               for n in descendants(handler.type)) or \
        looked_up and (any(isinstance(n, (ast.Name, ast.Attribute)) and
                           last_name(n) in _BROADER_CATCHES
                           for handler in going_on if handler.type
                           for n in descendants(handler.type)) or
                       any(handler.type is None for handler in going_on))


def _raises_again(handler: ast.ExceptHandler) -> bool:
    """True for a handler raising what it caught again (a bare ``raise``, or ``raise e`` of
    its ``as e``): it does not expect the failure."""
    return any(isinstance(n, ast.Raise) and (n.exc is None or isinstance(n.exc, ast.Name) and
                                             n.exc.id == handler.name)
               for n in descendants(handler))


def presence_flags(tree: ast.Module) -> frozenset[str]:
    """Names a launch file sets from whether a package is installed: ``True`` assigned in a
    ``try`` that checks for one (``found = True`` after the lookup), or what a function of
    the file with such a ``try``, returning only ``True`` or ``False``, returns (``has_mux =
    package_available('twist_mux')``)."""
    tries = [n for n in nodes_of_class(tree, ast.Try)
             if isinstance(n, ast.Try) and _checks_presence(n)]
    checking = {id(n) for n in tries}
    probes = {f.name for f in nodes_of_class(tree, ast.FunctionDef, ast.AsyncFunctionDef)
              if isinstance(f, (ast.FunctionDef, ast.AsyncFunctionDef)) and
              any(id(n) in checking for n in descendants(f)) and _answers_yes_or_no(f)}
    flags = {target.id for block in tries for statement in block.body
             if isinstance(statement, ast.Assign) and isinstance(statement.value, ast.Constant)
             and statement.value.value is True
             for target in statement.targets if isinstance(target, ast.Name)}
    if probes:
        flags.update(target.id for node in nodes_of_class(tree, ast.Assign)
                     if isinstance(node, ast.Assign) and isinstance(node.value, ast.Call) and
                     last_name(node.value.func) in probes
                     for target in node.targets if isinstance(target, ast.Name))
    return frozenset(flags)


def _answers_yes_or_no(function: ast.FunctionDef | ast.AsyncFunctionDef) -> bool:
    """True when every ``return`` of ``function`` gives ``True`` or ``False`` (a probe, not a
    loader that returns what it found)."""
    returns = [n for n in descendants(function) if isinstance(n, ast.Return)]
    return bool(returns) and all(isinstance(r.value, ast.Constant) and
                                 isinstance(r.value.value, bool) for r in returns)


def read_python_launch(path: str, tree: ast.Module, exported: frozenset[str] = frozenset()
                       ) -> tuple[tuple[NodeRef, ...], tuple[PackageRef, ...],
                                  tuple[FileRef, ...]]:
    """The nodes, package lookups and share files of a parsed Python launch file (or module:
    ``exported`` are the names other modules may import from it)."""
    reader = _Reader(path, tree, exported)
    reader.visit(tree)
    checked = reader.checked
    files = [replace(f, checked=checked is None or any(
        f.package == package and f.parts[:len(parts)] == parts for package, parts in checked))
        for f in reader.files if not any(
            _extends(o, f, (f.package, f.parts) in reader.extended) for o in reader.files)]
    unique = {(f.package, f.parts, f.span.line): f for f in reversed(files)}
    return (tuple(reader.nodes), tuple(reader.packages),
            tuple(sorted(unique.values(), key=lambda f: (f.span.line, f.span.col))))


_ARGUMENT_LISTS = ("arguments", "ros_arguments")
"""Node keywords taking a list of command-line arguments."""
_TEXT_LISTS = (*_ARGUMENT_LISTS, "remappings")
"""Node keywords whose list items (or pairs' items) launch takes as text or substitutions."""


_JOINED_WORDS = lazy_pattern(r"\s*-[\w-]+\s+[^\s-]|\s*[\w./:-]+\s+--?[A-Za-z][\w-]*(?:[\s=]|$)")
"""One command-line item holding an option and its value (``-r in:=/x``, ``--log-level
debug``) or a word and an option (``serial --dev /dev/ttyACM0``)."""


_SHORT_OPTION_GLUED = lazy_pattern(r"\s*-[A-Za-z]\s+[^\s-]\S*\s*")
"""A one-letter option and its value in one item (``'-z 0.5'``): Python's argparse and
getopt take the rest of the item as the option's value (``' 0.5'``, which ``float()``
reads), as they take ``-z0.5``."""


def _joined_words(value: ast.expr | None, ros_arguments: bool) -> Iterator[ast.Constant]:
    """String literals of a list or tuple display that hold several command-line words (not
    the value of an option before them, which may well be a line of words the program splits
    itself: ``'--controller-ros-args', '-r a:=b'``; not a one-letter option glued to its
    value before ``--ros-args`` (``ros_arguments``: all are ROS's), which the program's
    argparse reads; the caller leaves out ``shell=True`` actions, whose shell splits the
    joined line again)."""
    items = value.elts if isinstance(value, (ast.List, ast.Tuple)) else []
    for before, item in zip([None, *items], items):
        ros_arguments = ros_arguments or isinstance(before, ast.Constant) and \
            before.value == "--ros-args"
        if isinstance(item, ast.Constant) and isinstance(item.value, str) and \
                _JOINED_WORDS.match(item.value) and not _takes_a_value(before) and \
                (ros_arguments or not _SHORT_OPTION_GLUED.fullmatch(item.value)):
            yield item


def _takes_a_value(item: ast.expr | None) -> bool:
    """True for an option item (``--controller-ros-args``) the next item may be the value of;
    not ``--ros-args`` or ``--``, after which every item is a word of its own."""
    return isinstance(item, ast.Constant) and isinstance(item.value, str) and \
        item.value.startswith("-") and item.value not in ("--ros-args", "--")


def _non_text(value: ast.expr | None) -> Iterator[ast.Constant]:
    """Number and bool literals in a list or tuple display (or in its tuples, for pairs)."""
    items = value.elts if isinstance(value, (ast.List, ast.Tuple)) else []
    for item in items:
        inner = item.elts if isinstance(item, ast.Tuple) else [item]
        yield from (i for i in inner if isinstance(i, ast.Constant) and
                    i.value is not None and not isinstance(i.value, str))


def _find_of_a_lookup(node: ast.Call) -> bool:
    """True for ``FindPackageShare(...).find(...)`` (or ``FindPackagePrefix``'s)."""
    return isinstance(node.func, ast.Attribute) and node.func.attr == "find" and \
        isinstance(node.func.value, ast.Call) and \
        last_name(node.func.value.func) in ("FindPackageShare", "FindPackagePrefix")


def _refinding(node: ast.Call) -> bool:
    """True for ``FindPackageShare(x).find(y)`` given its own package name ``y``: the
    method looks up ``y`` alone (``x`` is never used)."""
    return bool(node.args) and _find_of_a_lookup(node)
