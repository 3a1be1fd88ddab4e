"""What DAT009-DAT011 and PYC014 share: the parameters a package's Node subclasses declare,
the nodes its launch files pass each parameter file to, and rcl's typing of YAML values.

A class is analysed only when it derives from rclpy's ``Node`` directly; a ``skip`` reason
says why its declarations are not known in full (undeclared parameters allowed, a name that
is not a literal, a project base class, ``self`` handed to other code).
"""

from __future__ import annotations

import ast
import builtins
import posixpath
import re
from difflib import get_close_matches
from collections.abc import Iterable, Iterator

from pkgtool.knowledge.rosdistro import any_stdlib_module, typo_distance, typo_of
from pkgtool.model.ast_nodes import last_name, nodes_of_class, subtree, walk_once
from pkgtool.model.installed import installed_data
from pkgtool.model.launch import NodeRef
from pkgtool.model.memo import per_package
from pkgtool.model.package import Package
from pkgtool.model.python_visitor import parse_tree
from pkgtool.model.span import Span
from pkgtool.records import record
from pkgtool.rules.console_scripts import scripts_and_modules
from pkgtool.rules.launch_includes import own_includes
from pkgtool.rules.node_api import NODE_CLASSES, name_argument, node_constructions
from pkgtool.rules.scopes import single_assignments
from pkgtool.rules.syntax_trees import Index, installed_trees
from pkgtool.rules.test_modules import test_files
from pkgtool.lazy_regex import lazy_pattern

PERMISSIVE = frozenset({"allow_undeclared_parameters",
                        "automatically_declare_parameters_from_overrides"})
"""Node options that accept parameters nobody declares."""
READS = frozenset({"get_parameter", "get_parameters"})
"""Node methods that raise ParameterNotDeclaredException for an undeclared name."""
SETS = frozenset({"set_parameters", "set_parameters_atomically"})
"""Node methods that set parameters (ParameterNotDeclaredException for an undeclared one)."""
PARAMETER_CLASSES = frozenset({"rclpy.parameter.Parameter", "rclpy.Parameter"})
"""What ``Parameter`` objects are made with."""
DECLARES = frozenset({"declare_parameter", "declare_parameters"})
"""Node methods that declare parameters."""
BUILT_IN = frozenset({"use_sim_time", "start_type_description_service"})
"""Parameters rclpy's Node declares itself (Jazzy)."""
SIM_TIME = "use_sim_time"
"""The parameter every ROS 2 node has: take the time from ``/clock`` (a simulator's)."""


def sim_time_typo(name: str) -> bool:
    """True when the last part of a parameter name is one edit (a letter added, dropped or
    replaced, two neighbours swapped) from ``use_sim_time``, or it with other separators
    (``use-sim-time``, ``usesimtime``) (DAT025's to report; DAT010 leaves it alone). Two
    edits make real names (``use_imu_time``)."""
    last = name.rpartition(".")[2]
    return last != SIM_TIME and (typo_distance(last, SIM_TIME, budget=1) <= 1 or
                                 re.sub(r"[-_ ]", "", last).lower() == "usesimtime")


_BOOLS = frozenset({"Y", "y", "yes", "Yes", "YES", "true", "True", "TRUE", "on", "On", "ON",
                    "N", "n", "no", "No", "NO", "false", "False", "FALSE", "off", "Off", "OFF"})
"""Plain scalars rcl's YAML parameter parser reads as booleans."""
_INT = lazy_pattern(r"[+-]?(0[xX][0-9a-fA-F]+|0[0-7]*|[1-9][0-9]*)")
_FLOAT = lazy_pattern(r"[+-]?((\d+\.?\d*|\.\d+)([eE][+-]?\d+)?|inf|infinity|nan)", re.I)
_SPECIAL_FLOATS = frozenset(f"{sign}.{word}" for sign in ("", "+", "-")
                            for word in ("inf", "Inf", "INF")) | {".nan", ".NaN", ".NAN"}


@record
class Declared:
    """A parameter a class declares: its full name, the ROS type of its literal default (None:
    not a literal, or the type is not checked: dynamic typing, an unknown descriptor,
    ``ignore_override``) and where it is declared."""

    name: str
    type: str | None
    span: Span


@record
class NodeClass:
    """A class of installed code that is a node: its default node name (the literal passed to
    ``super().__init__``, else None), declared parameters, literal ``get_parameter`` reads,
    when its declarations are not known in full, why, and the literal names of the
    ``Parameter`` objects it hands to its own ``set_parameters``."""

    path: str
    name: str
    default_name: str | None
    declared: tuple[Declared, ...]
    reads: tuple[tuple[str, Span], ...]
    skip: str | None
    sets: tuple[tuple[str, Span], ...] = ()

    def declares(self, parameter: str) -> Declared | None:
        """The declaration of ``parameter``, if the class has one."""
        return next((d for d in self.declared if d.name == parameter), None)


def _literal_string(node: ast.expr | None) -> str | None:
    return node.value if isinstance(node, ast.Constant) and isinstance(node.value, str) \
        else None


def _argument(call: ast.Call, position: int, keyword: str) -> ast.expr | None:
    found = next((k.value for k in call.keywords if k.arg == keyword), None)
    if found is None and len(call.args) > position and \
            not any(isinstance(a, ast.Starred) for a in call.args[:position + 1]):
        found = call.args[position]
    return found


def python_type(value: object) -> str | None:
    """The ROS parameter type of a Python default (None for None, mixed or empty lists)."""
    scalar = {bool: "BOOL", int: "INTEGER", float: "DOUBLE", str: "STRING"}
    if type(value) in scalar:
        return scalar[type(value)]
    if isinstance(value, (list, tuple)) and value:
        kinds = {scalar.get(type(v)) for v in value}
        return f"{kinds.pop()}_ARRAY" if len(kinds) == 1 and None not in kinds else None
    return None


def _default_type(call: ast.Call, value: ast.expr | None, descriptor: ast.expr | None
                  ) -> str | None:
    """The checked type of a declaration's default (see :class:`Declared`)."""
    if value is None or literal_flag(call, "ignore_override") is not False or not static_typing(
            descriptor):
        return None
    try:
        return python_type(ast.literal_eval(value))
    except (ValueError, TypeError, SyntaxError, MemoryError, RecursionError):
        return None


def literal_flag(call: ast.Call, keyword: str) -> bool | None:
    """A keyword's literal boolean: False when absent, None when not a literal."""
    found = next((k.value for k in call.keywords if k.arg == keyword), None)
    if found is None:
        return False
    return found.value if isinstance(found, ast.Constant) and \
        isinstance(found.value, bool) else None


def static_typing(descriptor: ast.expr | None) -> bool:
    """True when no descriptor, or a ``ParameterDescriptor(...)`` without dynamic typing."""
    if descriptor is None:
        return True
    return isinstance(descriptor, ast.Call) and \
        getattr(descriptor.func, "id", getattr(descriptor.func, "attr", "")) == \
        "ParameterDescriptor" and literal_flag(descriptor, "dynamic_typing") is False


def _declarations(call: ast.Call, method: str, path: str, index: Index
                  ) -> list[Declared] | None:
    """The parameters a call of ``method`` (``declare_parameter(s)``) declares; None when not
    all literal (a ``parameters=`` list may be a local name bound once to one)."""
    span = Span(path, call.lineno, call.col_offset + 1)
    if method == "declare_parameter":
        name = _literal_string(_argument(call, 0, "name"))
        if name is None:
            return None
        return [Declared(name, _default_type(call, _argument(call, 1, "value"),
                                             _argument(call, 2, "descriptor")), span)]
    namespace = _literal_string(_argument(call, 0, "namespace"))
    items = _argument(call, 1, "parameters")
    if isinstance(items, ast.Name):
        items = _list_bound_once(items, index)
    if namespace is None or not isinstance(items, (ast.List, ast.Tuple)):
        return None
    found: list[Declared] = []
    for item in items.elts:
        parts = item.elts if isinstance(item, ast.Tuple) else []
        name = _literal_string(parts[0]) if parts else None
        if name is None:
            return None
        full = f"{namespace}.{name}" if namespace else name
        found.append(Declared(full, _default_type(call, parts[1] if len(parts) > 1 else None,
                                                  parts[2] if len(parts) > 2 else None), span))
    return found


def _list_bound_once(name: ast.Name, index: Index) -> ast.expr | None:
    """The list or tuple display ``name`` is bound to by the one assignment of it in its
    function, when nothing there changes it (no other binding, no method call or item
    store on it); else None."""
    function = index.enclosing_function(name)
    if function is None:
        return None
    bound = [node for node in subtree(function) if isinstance(node, ast.Name) and
             node.id == name.id and not isinstance(node.ctx, ast.Load)]
    changed = any(isinstance(node, (ast.Attribute, ast.Subscript)) and
                  isinstance(node.value, ast.Name) and node.value.id == name.id and
                  (isinstance(node, ast.Attribute) or not isinstance(node.ctx, ast.Load))
                  for node in subtree(function))
    assignment = index.parents.get(id(bound[0])) if len(bound) == 1 else None
    return assignment.value if isinstance(assignment, ast.Assign) and not changed and \
        len(assignment.targets) == 1 and \
        isinstance(assignment.value, (ast.List, ast.Tuple)) else None


Scope = tuple[int, str]
"""A name in the function binding it: (``id`` of the function, or 0 at module level, name)."""


def _scope(index: Index, node: ast.AST, name: str) -> Scope:
    function = index.enclosing_function(node)
    return (id(function) if function is not None else 0), name


def _aliases(tree: ast.Module, index: Index) -> dict[Scope, str]:
    """Names bound only to ``x.declare_parameter(s)`` in their function: the method."""
    nodes = walk_once(tree).by_class
    bindings: dict[Scope, list[ast.AST]] = {}
    for node in nodes.get(ast.Name, ()):
        if not isinstance(node.ctx, ast.Load):  # type: ignore[attr-defined]
            bindings.setdefault(_scope(index, node, node.id), []).append(  # type: ignore
                index.parents.get(id(node), node))
    for node in nodes.get(ast.arg, ()):
        bindings.setdefault(_scope(index, node, node.arg), []).append(node)  # type: ignore
    aliases: dict[Scope, str] = {}
    for scope, binders in bindings.items():
        methods = {b.value.attr if isinstance(b, ast.Assign) and len(b.targets) == 1 and
                   isinstance(b.value, ast.Attribute) and b.value.attr in DECLARES else None
                   for b in binders}
        if len(methods) == 1 and None not in methods:
            aliases[scope] = methods.pop()  # type: ignore[assignment]
    return aliases


def _declaring_calls(tree: ast.Module, index: Index) -> list[tuple[ast.Call, str] | None]:
    """Each call declaring parameters with its method: ``x.declare_parameter(...)``, or
    ``p(...)`` where every binding of ``p`` in its function is ``p = x.declare_parameter``.
    None for a reference to the methods used otherwise (passed on, or bound to a name that
    stands for other things too): what it declares is not known."""
    aliases = _aliases(tree, index)
    found: list[tuple[ast.Call, str] | None] = []
    for node in index.attributes:
        parent = index.parents.get(id(node))
        if node.attr in DECLARES and not (isinstance(parent, ast.Call) and parent.func is node) \
                and not (isinstance(parent, ast.Assign) and isinstance(parent.targets[0], ast.Name)
                         and _scope(index, parent, parent.targets[0].id) in aliases):
            found.append(None)
    for call in index.calls:
        if isinstance(call.func, ast.Attribute) and call.func.attr in DECLARES:
            found.append((call, call.func.attr))
        elif isinstance(call.func, ast.Name) and _scope(index, call, call.func.id) in aliases:
            found.append((call, aliases[_scope(index, call, call.func.id)]))
    return found


_NODE_USERS = frozenset({"ActionClient", "ActionServer", "TransformListener",
                         "TransformBroadcaster", "StaticTransformBroadcaster", "Buffer",
                         "Subscriber", "Cache", "spin", "spin_once",
                         "spin_until_future_complete"})
"""Classes and functions of rclpy, tf2_ros and message_filters that take a node and declare
no parameter on it."""
_NODE_USER_MODULES = frozenset({"rclpy", "tf2_ros", "message_filters"})


_LOOKS_AT_IT = frozenset({"hasattr", "isinstance", "id", "repr", "str", "print", "len",
                          "type", "super", "vars", "callable", "hash", "format"})
"""Built-in functions that only look at what they are given (``hasattr(self, 'timer')``,
``super(MyNode, self)``): none declares a parameter on it."""


def _declares_nothing(call: ast.Call, index: Index) -> bool:
    """True for a call of :data:`_NODE_USERS` (imported from :data:`_NODE_USER_MODULES`),
    an executor's ``add_node`` or a built-in of :data:`_LOOKS_AT_IT`: handed the node, it
    declares no parameter."""
    func = call.func
    if isinstance(func, ast.Attribute) and func.attr == "add_node":
        return True
    if isinstance(func, ast.Name) and func.id in _LOOKS_AT_IT and func.id not in index.bound:
        return True
    dotted = index.qualified(func) if isinstance(func, (ast.Name, ast.Attribute)) else None
    return dotted is not None and dotted.split(".")[0] in _NODE_USER_MODULES and \
        dotted.rsplit(".", 1)[-1] in _NODE_USERS


def _is_self(node: ast.expr) -> bool:
    return isinstance(node, ast.Name) and node.id == "self"


def _node_class(path: str, cls: ast.ClassDef, index: Index, module_skip: str | None,
                declaring: list[tuple[ast.Call, str] | None]) -> NodeClass:
    """The analysis of one direct Node subclass."""
    inside = [c for c in index.calls if _within(index, c, cls)]
    name = next((_literal_string(name_argument(c)) for c in node_constructions(index)
                 if _within(index, c, cls) and isinstance(c.func, ast.Attribute)), None)
    declared: list[Declared] = []
    skip = module_skip
    if len(cls.bases) != 1 or cls.keywords:
        skip = skip or "it derives from another class besides Node"
    for call in declaring:
        found = None if call is None else _declarations(*call, path, index)
        if found is None:
            skip = skip or "it declares a parameter whose name is not known statically"
        else:
            declared.extend(found)
    if any(_is_self(a) for c in inside if not _declares_nothing(c, index)
           for a in (*c.args, *(k.value for k in c.keywords))):
        skip = skip or "it hands `self` to other code, which may declare parameters"
    reads = [(n, Span(path, c.lineno, c.col_offset + 1))
             for c in inside if isinstance(c.func, ast.Attribute) and
             c.func.attr in READS and _is_self(c.func.value) for n in _read_names(c)]
    sets = [(n, Span(path, c.lineno, c.col_offset + 1))
            for c in inside if isinstance(c.func, ast.Attribute) and
            c.func.attr in SETS and _is_self(c.func.value) for n in _set_names(c, index)]
    return NodeClass(path, cls.name, name, tuple(declared), tuple(reads), skip, tuple(sets))


def _set_names(call: ast.Call, index: Index) -> list[str]:
    """Literal names of the ``Parameter`` objects a ``set_parameters([...])`` call lists, made
    in the list or bound once in the function to a name the list holds."""
    listed = call.args[0] if len(call.args) == 1 and not call.keywords else None
    if not isinstance(listed, (ast.List, ast.Tuple)):
        return []
    function = index.enclosing_function(call)
    made = [item if isinstance(item, ast.Call) else
            single_assignments(function).get(item.id) if isinstance(item, ast.Name) and function
            else None
            for item in listed.elts]
    return [name for item in made if isinstance(item, ast.Call) and
            index.qualified(item.func) in PARAMETER_CLASSES and item.args and
            (name := _literal_string(item.args[0])) is not None]


def _read_names(call: ast.Call) -> list[str]:
    """Literal parameter names a ``get_parameter(s)`` call reads."""
    assert isinstance(call.func, ast.Attribute)
    first = _argument(call, 0, "name" if call.func.attr == "get_parameter" else "names")
    items = first.elts if call.func.attr == "get_parameters" and \
        isinstance(first, (ast.List, ast.Tuple)) else [first]
    return [n for n in map(_literal_string, items) if n is not None]


def _within(index: Index, node: ast.AST, cls: ast.ClassDef) -> bool:
    parent = index.parents.get(id(node))
    while parent is not None and parent is not cls:
        parent = index.parents.get(id(parent))
    return parent is cls


def _module_skip(tree: ast.Module) -> str | None:
    """Why the module's parameter reads are not judged: it uses a :data:`PERMISSIVE` option,
    as a keyword or as a key of the keywords it passes (``options['allow_undeclared_parameters']
    = True``, ``super().__init__('n', **options)``)."""
    for node in nodes_of_class(tree, ast.keyword, ast.Constant):
        name = node.arg if isinstance(node, ast.keyword) else getattr(node, "value", None)
        if isinstance(name, str) and name in PERMISSIVE:
            return f"it uses `{name}`"
    return None


@per_package
def makes_a_declaring_node(package: Package) -> bool:
    """True when an installed module makes a :data:`_DECLARING_EVERYTHING` node: one of the
    package's processes may hand it the parameters a launch file gives any node of it."""
    return any(last_name(call.func) in _DECLARING_EVERYTHING  # type: ignore[attr-defined]
               for _, tree, _ in installed_trees(package)
               for call in nodes_of_class(tree, ast.Call))


_DECLARING_EVERYTHING = frozenset({"MoveItPy"})
"""Classes whose own node (in the same process) declares every parameter it is given: the
launch file's parameters may be meant for it."""


@record
class ModuleNodes:
    """The nodes of one installed module: its direct Node subclasses, whether it defines
    other classes (a node may derive from them), and the literal names of Node() calls."""

    classes: tuple[NodeClass, ...]
    other_classes: bool
    constructed: tuple[str | None, ...]


@per_package
def module_nodes(package: Package) -> dict[str, ModuleNodes]:
    """Every installed, parseable module's :class:`ModuleNodes`, by path."""
    found: dict[str, ModuleNodes] = {}
    for module, tree, index in installed_trees(package):
        skip = _module_skip(tree)
        direct = [c for c in index.classes
                  if any(index.qualified(b) in NODE_CLASSES for b in c.bases)]
        calls = tuple(_literal_string(name_argument(c)) for c in index.calls
                      if index.qualified(c.func) in NODE_CLASSES)
        declaring = _declaring_calls(tree, index) if direct else []
        found[module.path] = ModuleNodes(
            tuple(_node_class(module.path, c, index, skip, declaring) for c in direct),
            any(c not in direct and _may_be_a_node(c, index) for c in index.classes), calls)
    return found


def _may_be_a_node(cls: ast.ClassDef, index: Index) -> bool:
    """False for a class that derives from nothing (``class PController:``, ``(object)``) or
    only from Python's own classes (``class Mode(Enum)``, ``(Exception)``, ``(Thread)``): it
    cannot be a node; any other may be one through its bases."""
    return cls.keywords != [] or not all(_python_class(b, index) for b in cls.bases)


def _python_class(base: ast.expr, index: Index) -> bool:
    """True for a base that is a builtin class (``object``, ``Exception``) or a class of the
    standard library (``enum.Enum``, ``threading.Thread``, ``typing.NamedTuple``)."""
    if isinstance(base, ast.Name) and base.id not in index.bound:
        return isinstance(getattr(builtins, base.id, None), type)
    qualified = index.qualified(base) if isinstance(base, (ast.Name, ast.Attribute)) else None
    return qualified is not None and "." in qualified and \
        qualified.split(".")[0] in any_stdlib_module()


def node_classes(package: Package) -> Iterator[NodeClass]:
    """Every direct Node subclass of installed code."""
    for nodes in module_nodes(package).values():
        yield from nodes.classes


@per_package
def executable_nodes(package: Package) -> dict[str, tuple[str | None, NodeClass | None]]:
    """Console script -> (default node name, Node class) of the node its module runs.

    Known when the module defines exactly one direct Node subclass (and besides it only
    classes deriving from nothing, helpers) and constructs no other node (the name then comes
    from ``super().__init__``), or defines no such class and constructs one node with
    ``Node('name')`` / ``create_node('name')`` (the class is None).
    A script missing from the result, or a None name, is not known.
    """
    entries, modules = scripts_and_modules(package)
    nodes = module_nodes(package)
    found: dict[str, tuple[str | None, NodeClass | None]] = {}
    for entry in entries:
        module = nodes.get(modules.get(entry.module, ""))
        if module is None or module.other_classes:
            continue
        if len(module.classes) == 1 and not module.constructed:
            found[entry.name] = (module.classes[0].default_name, module.classes[0])
        elif not module.classes and len(module.constructed) == 1:
            found[entry.name] = (module.constructed[0], None)
    return found


def node_name(package: Package, node: NodeRef) -> str | None:
    """The name a launched node runs under (static name, or its code's default), if known."""
    if node.name_unknown:
        return None
    if node.name is not None:
        return node.name.rpartition("/")[2]
    if node.package != package.name or node.executable is None:
        return None
    return executable_nodes(package).get(node.executable, (None, None))[0]


def node_class(package: Package, node: NodeRef) -> NodeClass | None:
    """The Node class a launched node of this package runs, when known."""
    if node.package != package.name or node.executable is None:
        return None
    return executable_nodes(package).get(node.executable, (None, None))[1]


@per_package
def parameter_file_nodes(package: Package) -> dict[str, tuple[NodeRef, ...]]:
    """Package file -> the nodes the package's launch files pass it to as parameters."""
    data = installed_data(package) or {}
    found: dict[str, list[NodeRef]] = {}
    for launch in package.launch_files:
        for node in launch.nodes:
            for ref in node.parameter_files:
                if ref.package != package.name:
                    continue
                relative = posixpath.join(*ref.parts)
                source = data.get(posixpath.join("share", package.name, relative))
                for path in {p for p in (source, relative) if p and package.has_file(p)}:
                    found.setdefault(path, []).append(node)
    return {path: tuple(nodes) for path, nodes in found.items()}


def files_rcl_reads(package: Package) -> set[str]:
    """The package files a launch file passes to a plain node as parameters: rcl's parser reads
    them as written. (launch_ros reads a file passed only to components itself.)"""
    return {path for path, nodes in parameter_file_nodes(package).items()
            if not all(node.composable for node in nodes)}


def fully_seen_parameter_files(package: Package) -> dict[str, tuple[NodeRef, ...]]:
    """:func:`statically_used_parameter_files`, those whose users are every user: a node
    given parameters not read statically (a launch argument may name any file) may use any
    file, so a file is kept only when each such node is among its users already (the file
    is that argument's default)."""
    others = [n for f in package.launch_files for n in f.nodes if n.other_parameters]
    return {path: nodes for path, nodes in statically_used_parameter_files(package).items()
            if all(any(other is node for node in nodes) for other in others)}


@per_package
def statically_used_parameter_files(package: Package) -> dict[str, tuple[NodeRef, ...]]:
    """:func:`parameter_file_nodes`, for files whose users the launch files name.

    Empty when a launch file does not parse; a file whose name the package's Python code
    other than setup.py and tests mentions (it may read it itself), or that a launch file
    hands to a launch file it includes, is left out. A node given a file by a path worked
    out at run time may get any of them too: what the named users need still holds.
    """
    launches = package.launch_files
    if any(f.problem for f in launches):
        return {}
    skipped = {"setup.py", *(f.path for f in launches), *test_files(package)}  # setup.py
    # installs files and tests check them: neither hands the node its parameters
    code = [package.texts.get(p, "") for p in package.files
            if p.endswith(".py") and p not in skipped]
    code.append(_handed_to_includes(package))
    return {path: nodes for path, nodes in parameter_file_nodes(package).items()
            if not any(posixpath.basename(path) in text for text in code)}


_XML_INCLUDE = lazy_pattern(r"<include\b.*?(?:/>|</include>)", re.S)


def _handed_to_includes(package: Package) -> str:
    """The text of what the launch files hand to the launch files of other packages they
    include: a Python ``IncludeLaunchDescription``'s ``launch_arguments`` (with the values of
    the names it reads, as the module assigns them), an XML ``<include>`` element. A
    parameter file named there may reach nodes the included file starts, whose names pkgtool
    does not see (it sees those of the package's own launch files)."""
    own = {(include.path, include.line) for include in own_includes(package)}
    found: list[str] = []
    for launch in package.launch_files:
        text = package.texts.get(launch.path, "")
        if launch.kind == "xml":
            found += [element.group(0) for element in _XML_INCLUDE.finditer(text)
                      if (launch.path, text.count("\n", 0, element.start()) + 1) not in own]
            continue
        tree = parse_tree(launch.path, text) if launch.kind == "python" and \
            "IncludeLaunchDescription" in text else None
        if not isinstance(tree, ast.Module):
            continue
        values = {target.id: node.value for node in nodes_of_class(tree, ast.Assign)
                  for target in node.targets if isinstance(target, ast.Name)}
        for call in nodes_of_class(tree, ast.Call):
            func = call.func
            name = func.id if isinstance(func, ast.Name) else \
                func.attr if isinstance(func, ast.Attribute) else ""
            handed = [k.value for k in call.keywords if k.arg == "launch_arguments"] + \
                call.args[1:2] if name.endswith("IncludeLaunchDescription") and \
                (launch.path, call.lineno) not in own else []
            for part in handed:
                found.append(ast.unparse(part))
                found += [ast.unparse(values[n.id]) for n in ast.walk(part)
                          if isinstance(n, ast.Name) and n.id in values]
    return "\n".join(found)


def yaml_type(node: object) -> str | None:
    """The ROS type rcl's parameter parser gives a YAML value (None: not known, or rejected:
    an empty or mixed list, an empty or out-of-range value)."""
    import yaml

    if isinstance(node, yaml.SequenceNode):
        kinds = {scalar_type(v) if isinstance(v, yaml.ScalarNode) else None for v in node.value}
        return f"{kinds.pop()}_ARRAY" if len(kinds) == 1 and None not in kinds else None
    return scalar_type(node) if isinstance(node, yaml.ScalarNode) else None


def mixed_list(node: object) -> bool:
    """True for a YAML list of scalars of different ROS types, which rcl rejects."""
    import yaml

    if not isinstance(node, yaml.SequenceNode) or \
            not all(isinstance(v, yaml.ScalarNode) for v in node.value):
        return False
    kinds = {scalar_type(v) for v in node.value}
    return None not in kinds and len(kinds) > 1


def scalar_type(node: object) -> str | None:
    """rcl's ``get_value``: quoted -> STRING; plain: bool words, ``strtol``, ``strtod``."""
    text = str(getattr(node, "value", ""))
    if getattr(node, "style", None) in ("'", '"'):
        return "STRING"
    if not text or getattr(node, "tag", "").startswith("tag:yaml.org,2002:") is False:
        return None
    if text in _BOOLS:
        return "BOOL"
    if _INT.fullmatch(text):
        return "INTEGER" if -2 ** 63 <= int(text, 8 if _octal(text) else 0) < 2 ** 63 else None
    if text in _SPECIAL_FLOATS:
        return "DOUBLE"
    if _FLOAT.fullmatch(text):
        value = float(text)
        return "DOUBLE" if value not in (float("inf"), -float("inf")) or "inf" in \
            text.lower() else None
    return "STRING"


def _octal(text: str) -> bool:
    digits = text.lstrip("+-")
    return len(digits) > 1 and digits[0] == "0" and digits[1] not in "xX"


_MERGE = "tag:yaml.org,2002:merge"
"""The tag of a YAML merge key (``<<``)."""


def _merged_items(mapping: object, depth: int = 0) -> list[tuple[object, object]]:
    """The (key, value) pairs of a YAML mapping with scalar keys, ``<<`` merges resolved as
    YAML 1.1 does: a key written in the mapping wins over merged ones, and of several merged
    mappings (``<<: [*a, *b]``) the first that has a key gives it."""
    import yaml

    own = [(k, v) for k, v in mapping.value  # type: ignore[attr-defined]
           if isinstance(k, yaml.ScalarNode) and k.tag != _MERGE]
    seen = {k.value for k, _ in own}
    found = list(own)
    for key, value in mapping.value:  # type: ignore[attr-defined]
        if not (isinstance(key, yaml.ScalarNode) and key.tag == _MERGE) or depth > 20:
            continue
        sources = value.value if isinstance(value, yaml.SequenceNode) else [value]
        for source in sources:
            if not isinstance(source, yaml.MappingNode):
                continue
            for merged_key, merged_value in _merged_items(source, depth + 1):
                if merged_key.value not in seen:
                    seen.add(merged_key.value)
                    found.append((merged_key, merged_value))
    return found


def flat_parameters(mapping: object, prefix: str = "", depth: int = 0
                    ) -> Iterator[tuple[str, object, object]]:
    """(dotted name, key node, value node) of every parameter under ``ros__parameters``
    (nested at most 20 deep: a mapping an alias puts inside itself never ends)."""
    import yaml

    if not isinstance(mapping, yaml.MappingNode) or depth > 20:
        return
    for key, value in _merged_items(mapping):
        name = f"{prefix}{key.value}"
        if isinstance(value, yaml.MappingNode):
            yield from flat_parameters(value, name + ".", depth + 1)
        else:
            yield name, key, value


@record
class FileEntry:
    """A ``<node>: ros__parameters:`` block of a parameter file whose users are all known:
    the node key (namespaces joined with ``/``), where it is written, the launched nodes it
    applies to, every node the file is passed to with their names, the parameters, and
    whether the file is passed to a node of another package (whose process may hold nodes of
    its own: Nav2's servers make ``local_costmap/local_costmap``)."""

    path: str
    key: str
    span: Span
    matched: tuple[NodeRef, ...]
    names: tuple[str, ...]
    parameters: object
    foreign: bool = False


def key_matches(key: str, name: str) -> bool:
    """True when a parameter file's node key (its last part, a glob) names ``name``."""
    from fnmatch import fnmatchcase

    return fnmatchcase(name, key.rpartition("/")[2])


def file_entries(package: Package, *, unseen_users: bool = False) -> Iterator[FileEntry]:
    """The node blocks of every fully seen parameter file whose nodes all have known names;
    with ``unseen_users``, also of files a node may get by a path worked out at run time
    (what the nodes the launch files name need of a file holds whoever else reads it)."""
    from pkgtool.model.launch_reader import yaml_problem

    files = statically_used_parameter_files(package) if unseen_users else \
        fully_seen_parameter_files(package)
    for path, nodes in sorted(files.items()):
        names = [node_name(package, n) for n in nodes]
        text = package.texts.get(path)
        documents = yaml_problem(path, text) if text is not None else None
        if None in names or not isinstance(documents, list):
            continue
        known = tuple(n for n in names if n is not None)
        foreign = any(n.package != package.name for n in nodes)
        for document in documents:
            for key, span, parameters in parameter_blocks(path, document):
                matched = tuple(n for n, name in zip(nodes, known) if key_matches(key, name))
                yield FileEntry(path, key, span, matched, tuple(sorted(set(known))), parameters,
                                foreign)


def parameter_blocks(path: str, mapping: object, prefix: str = "", depth: int = 0
                     ) -> Iterator[tuple[str, Span, object]]:
    """(node key, where it is written, its ``ros__parameters`` mapping) of each node block of
    a composed YAML document, namespaces joined with ``/``."""
    import yaml

    if not isinstance(mapping, yaml.MappingNode) or depth > 20:
        return
    for key, value in mapping.value:
        if not isinstance(key, yaml.ScalarNode) or not isinstance(value, yaml.MappingNode):
            continue
        name = f"{prefix}/{key.value}" if prefix else str(key.value)
        inner = {str(k.value): v for k, v in value.value if isinstance(k, yaml.ScalarNode)}
        if "ros__parameters" in inner:
            yield name, Span(path, key.start_mark.line + 1, key.start_mark.column + 1), \
                inner["ros__parameters"]
        else:
            yield from parameter_blocks(path, value, name, depth + 1)


def analysed_classes(package: Package, nodes: tuple[NodeRef, ...]) -> list[NodeClass] | None:
    """The Node classes ``nodes`` run, when every one is known and declares only literals."""
    classes = [node_class(package, n) for n in nodes]
    if not classes or any(c is None or c.skip for c in classes):
        return None
    return [c for c in classes if c is not None]


def span_of(path: str, node: object) -> Span:
    """Where a YAML node starts."""
    mark = getattr(node, "start_mark")
    return Span(path, mark.line + 1, mark.column + 1)


def near(word: str, choices: list[str] | tuple[str, ...]) -> str:
    """`` (did you mean `x`?)`` for a close match of ``word``, else ''."""
    found = get_close_matches(word, sorted(set(choices)), n=1)
    return f" (did you mean `{found[0]}`?)" if found else ""


def write_meant(word: str, choices: Iterable[str]) -> str | None:
    """``Write `x``` when exactly one of ``choices`` is a typo away from ``word`` (the help a
    fixer acts on), else None."""
    meant = typo_of(word, choices)
    return f"Write `{meant}`" if meant else None
