"""What PYC021, PYC022, PYC067 and LCH014 share: the publishers and subscriptions (services and
clients) of a package's installed modules whose topic (service) name is certain, with their
interface type and QoS when known.

A topic name is certain when it is a string literal, a name bound once in its function (or
module) to one, or a parameter read (``self.get_parameter('topic').value``) the class
declares once with a literal string default that no parameter file or launch file of the
package may change: no parameter file block that may apply to the class sets it to another
value, no launch file quotes it. Topics a launch file quotes (it may remap them), private
names (``~/x``) and names with substitutions are left out.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Iterator

from pkgtool.model.ast_nodes import subtree
from pkgtool.model.launch import LaunchFile
from pkgtool.model.memo import per_package
from pkgtool.model.modules import PythonModule
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.records import record
from pkgtool.rules.node_api import (ACTION_PARAMETERS, ACTIONS, PARAMETERS, argument,
                                    node_api_calls, unpacks)
from pkgtool.rules.node_parameters import analysed_classes, file_entries, flat_parameters
from pkgtool.rules.scopes import bound_names
from pkgtool.rules.syntax_trees import FUNCTIONS, Index, installed_trees

_QOS = "rclpy.qos"
_PRESETS = {"qos_profile_sensor_data": ("BEST_EFFORT", "VOLATILE"),
            "qos_profile_default": ("RELIABLE", "VOLATILE"),
            "QoSPresetProfiles.SENSOR_DATA.value": ("BEST_EFFORT", "VOLATILE"),
            "QoSPresetProfiles.DEFAULT.value": ("RELIABLE", "VOLATILE")}
"""rclpy's predefined profiles whose reliability and durability are fixed (Jazzy)."""
_POLICIES = {"reliability": frozenset({"ReliabilityPolicy", "QoSReliabilityPolicy"}),
             "durability": frozenset({"DurabilityPolicy", "QoSDurabilityPolicy"})}
_VALUES = frozenset({"RELIABLE", "BEST_EFFORT", "VOLATILE", "TRANSIENT_LOCAL"})
_READS = frozenset({"value", "string_value"})


@record
class Endpoint:
    """A publisher or subscription: ``kind`` (``publisher``/``subscription``; for services
    ``server``/``client``, for actions ``action server``/``action client``), the topic
    (service or action name), its message (service, action) type
    (``pkg/Name``, None when unknown), its (reliability, durability) (None when unknown or a
    service), and where its type, QoS and topic arguments are; ``literal``: the topic is
    written there as a string (not a name or a parameter's default)."""

    kind: str
    topic: str
    type: str | None
    qos: tuple[str, str] | None
    type_span: Span
    qos_span: Span
    topic_span: Span
    literal: bool


@per_package
def endpoints(package: Package) -> tuple[Endpoint, ...]:
    """The package's publishers and subscriptions with a certain topic name."""
    return tuple(_endpoints(package, {"create_publisher": "publisher",
                                      "create_subscription": "subscription"},
                            ("topic", "msg_type"), "msg"))


@per_package
def service_endpoints(package: Package) -> tuple[Endpoint, ...]:
    """The package's services and clients (``kind``: ``server``/``client``, ``type``:
    ``pkg/Name`` of a ``pkg.srv.Name`` class), and its action servers and clients (``action
    server``/``action client``, of a ``pkg.action.Name`` class), with a certain name."""
    return tuple(_endpoints(package, {"create_service": "server", "create_client": "client"},
                            ("srv_name", "srv_type"), "srv")) + \
        tuple(_endpoints(package, {"ActionServer": "action server",
                                   "ActionClient": "action client"},
                         ("action_name", "action_type"), "action"))


def _calls(package: Package, kinds: dict[str, str]
           ) -> Iterator[tuple[PythonModule, ast.Call, str, tuple[str, ...], Index]]:
    """The calls of the node methods, or rclpy action classes, ``kinds`` names, each with the
    name of what is called and its positional parameters."""
    if kinds.keys() <= PARAMETERS.keys():
        for code, call, method, index in node_api_calls(package, kinds):
            yield code, call, method, PARAMETERS[method], index
        return
    for code, _, index in installed_trees(package):
        for call in index.calls:
            called = index.qualified(call.func) \
                if isinstance(call.func, (ast.Name, ast.Attribute)) else None
            if called in ACTIONS:
                yield code, call, called.rpartition(".")[2], ACTION_PARAMETERS, index


def _endpoints(package: Package, kinds: dict[str, str], names: tuple[str, str], module: str
               ) -> Iterator[Endpoint]:
    """The endpoints the node methods (or action classes) ``kinds`` make (-> kind), whose name
    argument (``names``: the name's and the type's parameters) is certain, with the type of
    their interface class (imported from ``<pkg>.<module>``) and, for topics, their QoS."""
    changed = _overrides(package)
    for code, call, method, parameters, index in _calls(package, kinds):
        name_expr, kind = (argument(call, parameters, name) for name in names)
        qos = argument(call, parameters, "qos_profile") if module == "msg" else None
        name = _text(name_expr, index, changed, code.path) if name_expr else None
        if name is None or name.startswith("~") or "{" in name or kind is None or \
                unpacks(call) or name.lstrip("/") in changed.anywhere:
            continue
        assert name_expr is not None
        yield Endpoint(
            kinds[method], name, _interface(kind, index, module, package),
            _profile(qos, index) if qos is not None else None,
            Span(code.path, kind.lineno, kind.col_offset + 1),
            Span(code.path, (qos or kind).lineno, (qos or kind).col_offset + 1),
            Span(code.path, name_expr.lineno, name_expr.col_offset + 1),
            isinstance(name_expr, ast.Constant))


def _interface(kind: ast.expr, index: Index, module: str, package: Package) -> str | None:
    """``pkg/Name`` of an interface class imported by name from ``pkg.<module>``, or None
    (also for a module of the package's own Python code, ``my_pkg/msg.py`` re-exporting
    another package's class: an ament_python package generates no interfaces)."""
    dotted = index.qualified(kind)
    parts = dotted.split(".") if dotted else []
    if len(parts) < 3 or parts[1] != module or any(
            package.has_file(f"{folder}{parts[0]}/{module}{end}")
            for folder in ("", "src/") for end in (".py", "/__init__.py")):
        return None
    return f"{parts[0]}/{parts[-1]}"


@record
class _Overrides:
    """Values the package's files may give parameters: ``by_class`` for the Node class
    (module path, class name) a parameter file block certainly applies to, ``anywhere`` for
    the others (``*``: any value, a launch file quotes the word)."""

    by_class: dict[tuple[str, str], dict[str, set[str]]]
    anywhere: dict[str, set[str]]


_QUOTED_WORD = re.compile(r"""(?:\b(executable|exec|package|pkg|name)\s*=\s*)?"""
                          r"""['"]/?(\w[\w.]*(?:/\w[\w.]*)*)['"]""")
"""A word a launch file quotes, with the keyword or attribute it is the value of, if one of
those naming a node's executable, package or name."""


def _quoted_words(launch: LaunchFile, text: str) -> Iterator[str]:
    """The words a launch file quotes, but as a node's executable or package, or the name of
    one of its nodes (``exec="safety_stop" name="safety_stop"``): what may be a topic it
    remaps or a parameter it sets (``<param name="topic">``, ``SetParameter(name=...)``)."""
    nodes = {node.name for node in launch.nodes if node.name}
    for keyword, word in _QUOTED_WORD.findall(text):
        if not keyword or keyword == "name" and word not in nodes:
            yield word


def _overrides(package: Package) -> _Overrides:
    by_class: dict[tuple[str, str], dict[str, set[str]]] = {}
    anywhere: dict[str, set[str]] = {}
    launches = {launch.path: launch for launch in package.launch_files}
    seen = set()
    for entry in file_entries(package):
        seen.add(entry.path)
        classes = analysed_classes(package, entry.matched) or [None]
        for name, _, value in flat_parameters(entry.parameters):
            for cls in classes:
                where = by_class.setdefault((cls.path, cls.name), {}) if cls else anywhere
                where.setdefault(name, set()).add(str(getattr(value, "value", "*")))
    for path, text in package.texts.items():
        if path.endswith((".yaml", ".yml")) and path not in seen:
            for key, value in re.findall(r"^\s*([\w.]+)\s*:\s*(.*?)\s*$", text, re.M):
                anywhere.setdefault(key, set()).add(value.strip("'\""))
        elif "launch" in path.rsplit("/", 1)[-1]:
            launch = launches.get(path)
            for word in _quoted_words(launch, text) if launch else \
                    (word for _, word in _QUOTED_WORD.findall(text)):
                anywhere.setdefault(word, set()).add("*")
    return _Overrides(by_class, anywhere)


def _scope_value(name: str, node: ast.AST, index: Index) -> ast.expr | None:
    """The value of the one assignment binding ``name`` in the function around ``node`` (or,
    when the function does not bind it, in the module)."""
    function = index.enclosing_function(node)
    scopes: list[ast.AST] = [function] if function is not None else []
    root: ast.AST = node
    while id(root) in index.parents:
        root = index.parents[id(root)]
    for scope in [*scopes, root]:
        count = bound_names(scope if isinstance(scope, FUNCTIONS) else
                            getattr(scope, "body", []))[name]
        if count == 0 and scope is not root:
            continue
        if count != 1:
            return None
        body = scope.body if isinstance(scope, (*FUNCTIONS, ast.Module)) else []
        values = [s.value for s in ast.walk(ast.Module(body=body, type_ignores=[]))
                  if isinstance(s, ast.Assign) and len(s.targets) == 1
                  and isinstance(s.targets[0], ast.Name) and s.targets[0].id == name]
        return values[0] if len(values) == 1 else None
    return None


def _text(expr: ast.expr, index: Index, changed: _Overrides, path: str) -> str | None:
    """The string ``expr`` certainly holds (see the module's doc), or None."""
    if isinstance(expr, ast.Constant):
        return expr.value if isinstance(expr.value, str) else None
    if isinstance(expr, ast.Name):
        value = _scope_value(expr.id, expr, index)
        return _text(value, index, changed, path) if value is not None \
            and not isinstance(value, ast.Name) else None
    name = _parameter_read(expr)
    if name is None:
        return None
    cls = index.enclosing_class(expr)
    defaults = [c.args[1] for c in index.calls if index.enclosing_class(c) is cls
                and isinstance(c.func, ast.Attribute) and c.func.attr == "declare_parameter"
                and len(c.args) > 1 and isinstance(c.args[0], ast.Constant)
                and c.args[0].value == name]
    default = defaults[0] if len(defaults) == 1 and isinstance(defaults[0], ast.Constant) \
        and isinstance(defaults[0].value, str) else None
    if cls is None or default is None:
        return None
    given = changed.by_class.get((path, cls.name), {}).get(name, set())
    if (given | changed.anywhere.get(name, set())) - {default.value}:
        return None
    return str(default.value)


def _parameter_read(expr: ast.expr) -> str | None:
    """``x`` of ``self.get_parameter('x').value`` (or ``.get_parameter_value().string_value``)."""
    if not (isinstance(expr, ast.Attribute) and expr.attr in _READS):
        return None
    call = expr.value
    if isinstance(call, ast.Call) and isinstance(call.func, ast.Attribute) \
            and call.func.attr == "get_parameter_value" and expr.attr == "string_value":
        call = call.func.value
    if isinstance(call, ast.Call) and isinstance(call.func, ast.Attribute) \
            and call.func.attr == "get_parameter" and isinstance(call.func.value, ast.Name) \
            and call.func.value.id == "self" and len(call.args) == 1 \
            and isinstance(call.args[0], ast.Constant) and isinstance(call.args[0].value, str):
        return call.args[0].value
    return None


def _profile(expr: ast.expr, index: Index) -> tuple[str, str] | None:
    """(reliability, durability) of a QoS argument: a history depth, one of rclpy's fixed
    profiles, or ``QoSProfile(...)`` with literal policies (directly, or through a name
    bound once to one and never changed)."""
    if isinstance(expr, ast.Constant) and type(expr.value) is int:
        return ("RELIABLE", "VOLATILE")
    if isinstance(expr, ast.Name) and (value := _scope_value(expr.id, expr, index)) is not None:
        function = index.enclosing_function(expr)
        stores = [n for n in subtree(function) if isinstance(n, ast.Attribute)
                  and isinstance(n.value, ast.Name) and n.value.id == expr.id
                  and not isinstance(n.ctx, ast.Load)] if function is not None else [expr]
        return None if stores or isinstance(value, ast.Name) else _profile(value, index)
    dotted = index.qualified(expr.func if isinstance(expr, ast.Call) else expr) or ""
    module, _, name = dotted.partition(".qos.")
    if module != "rclpy" or not name:
        return None
    if not isinstance(expr, ast.Call):
        return _PRESETS.get(name)
    if name != "QoSProfile" or expr.args or any(k.arg is None for k in expr.keywords):
        return None
    policies = {"reliability": "RELIABLE", "durability": "VOLATILE"}
    for keyword in expr.keywords:
        if keyword.arg in _POLICIES:
            value = index.qualified(keyword.value) or ""
            owner, _, policy = value.rpartition(".")
            if not owner.startswith(f"{_QOS}.") or owner.rsplit(".", 1)[1] not in \
                    _POLICIES[keyword.arg] or policy not in _VALUES:
                return None
            policies[keyword.arg] = policy
    return policies["reliability"], policies["durability"]


def by_topic(package: Package, services: bool = False
             ) -> Iterator[tuple[list[Endpoint], list[Endpoint]]]:
    """(publishers, subscriptions) of each topic that has both; with ``services``, (services,
    clients) of each service name, (action servers, action clients) of each action name."""
    topics: dict[tuple[bool, str], tuple[list[Endpoint], list[Endpoint]]] = {}
    for endpoint in service_endpoints(package) if services else endpoints(package):
        pair = topics.setdefault((endpoint.kind.startswith("action"), endpoint.topic), ([], []))
        pair[endpoint.kind.endswith(("subscription", "client"))].append(endpoint)
    yield from (pair for pair in topics.values() if all(pair))


_NATIVE_SOURCES = (".cpp", ".cc", ".cxx", ".c")
"""Suffixes of the C and C++ sources of nodes a CMake package builds beside its Python ones."""


def type_mismatches(package: Package, services: bool = False
                    ) -> Iterator[tuple[Endpoint, list[Endpoint], str]]:
    """Each subscription (with ``services``, client) whose type is none of the types of the
    publishers (servers) of its name, all of which are known, with those endpoints and their
    types as a message lists them (```a/B`, `c/D```). Nothing in a package with C or C++
    sources: its native nodes' endpoints are not read, and may be of the other type."""
    if any(path.endswith(_NATIVE_SOURCES) for path in package.files):
        return
    for offering, using in by_topic(package, services):
        offered = {endpoint.type for endpoint in offering}
        if None in offered:
            continue
        for endpoint in using:
            if endpoint.type is not None and endpoint.type not in offered:
                yield endpoint, offering, ", ".join(f"`{t}`" for t in sorted(offered))
