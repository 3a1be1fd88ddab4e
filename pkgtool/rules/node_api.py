"""What PYC007-PYC009, PYC013, PYC015, PYC017, PYC018, PYC020, PYC030 and PYC049 share: calls
of rclpy's API and their arguments, literals, Node constructions.

Only modules that import rclpy and do not define a method of the same name themselves are
looked at, so a project's own ``create_publisher`` wrapper is never judged by rclpy's signature.
"""

from __future__ import annotations

import ast
from collections.abc import Collection, Iterator

from pkgtool.model.ast_nodes import is_super_init
from pkgtool.model.installed import installed_modules
from pkgtool.model.memo import per_package, per_tree
from pkgtool.model.modules import PythonModule
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.scopes import plainly_decorated
from pkgtool.rules.syntax_trees import Index, installed_trees
from pkgtool.lazy_regex import lazy_pattern

PARAMETERS = {
    "create_publisher": ("msg_type", "topic", "qos_profile"),
    "create_lifecycle_publisher": ("msg_type", "topic", "qos_profile"),
    "create_subscription": ("msg_type", "topic", "callback", "qos_profile"),
    "create_service": ("srv_type", "srv_name", "callback"),
    "create_client": ("srv_type", "srv_name"),
}
"""Required parameters of rclpy ``Node`` methods (Jazzy), in order."""
INTERFACE = lazy_pattern(r"\w+\.(msg|srv|action)\.\w+")
"""The dotted name of a message, service or action class (``std_msgs.msg.String``)."""
_DISPLAYS = {ast.List: "list", ast.Tuple: "tuple", ast.Dict: "dict", ast.Set: "set",
             ast.JoinedStr: "str"}
"""Literal displays and the type they build."""
NODE_CLASSES = frozenset({"rclpy.node.Node", "rclpy.lifecycle.LifecycleNode",
                          "rclpy.lifecycle.Node", "rclpy.create_node"})
"""What constructs a node: rclpy's node classes and ``create_node``."""
CALLBACKS: dict[str, tuple[tuple[str, ...], tuple[str, ...]]] = {
    "create_subscription": (("msg_type", "topic", "callback"), ("callback",)),
    "create_service": (("srv_type", "srv_name", "callback"), ("callback",)),
    "create_timer": (("timer_period_sec", "callback"), ("callback",)),
    "create_guard_condition": (("callback",), ("callback",)),
    "add_on_set_parameters_callback": (("callback",), ("callback",)),
    "add_pre_set_parameters_callback": (("callback",), ("callback",)),
    "add_post_set_parameters_callback": (("callback",), ("callback",)),
    "send_goal_async": (("goal", "feedback_callback"), ("feedback_callback",)),
    "send_goal": (("goal", "feedback_callback"), ("feedback_callback",)),
    "add_done_callback": (("callback",), ("callback",)),
}
"""rclpy methods (Jazzy) taking callables: their leading positional parameters, in order, and
which of them (or of their keyword-only parameters) are callbacks."""
INITS = frozenset({"rclpy.init", "rclpy.utilities.init"})
"""rclpy's init function, by the names it is imported through."""
SHUTDOWNS = frozenset({"rclpy.shutdown", "rclpy.utilities.shutdown"})
"""``rclpy.shutdown`` by the names a module imports it through (it raises once shut down)."""
TRY_SHUTDOWNS = frozenset({"rclpy.try_shutdown", "rclpy.utilities.try_shutdown"})
"""``rclpy.try_shutdown``, by the names it is imported through."""
ADD_NODE = "add_node"
"""The executor method taking the node (``Executor.add_node(node)``)."""
SPINS = {"rclpy.spin": ("node",), "rclpy.spin_once": ("node",),
         "rclpy.spin_until_future_complete": ("node", "future")}
"""rclpy's spin functions (Jazzy) and their required parameters, in order."""
ACTION_SERVERS = frozenset({"rclpy.action.ActionServer", "rclpy.action.server.ActionServer"})
ACTION_SERVER_CALLBACKS = (("node", "action_type", "action_name", "execute_callback"),
                           ("execute_callback", "goal_callback", "handle_accepted_callback",
                            "cancel_callback"))
"""``ActionServer.__init__``'s positional parameters and its callbacks (Jazzy)."""
ACTION_CLIENTS = frozenset({"rclpy.action.ActionClient", "rclpy.action.client.ActionClient"})
ACTIONS = ACTION_SERVERS | ACTION_CLIENTS
"""rclpy's action client and server classes, whose first parameters are..."""
ACTION_PARAMETERS = ("node", "action_type", "action_name")
"""... these, which both require (Jazzy)."""


def node_api_calls(package: Package, methods: Collection[str] = PARAMETERS
                   ) -> Iterator[tuple[PythonModule, ast.Call, str, Index]]:
    """``x.<method>(...)`` calls of ``methods`` (:data:`PARAMETERS`), with the method name;
    not where ``x`` is certainly no node (:func:`not_from_rclpy`)."""
    own = _own_tops(package)
    for module, call, method, index in _method_calls(package):
        receiver = call.func.value  # type: ignore[attr-defined]
        if method in methods and not not_from_rclpy(receiver, index) and \
                not _made_elsewhere(receiver, index, own):
            yield module, call, method, index


@per_package
def _own_tops(package: Package) -> frozenset[str]:
    """The top-level names of the modules setup.py installs, or when that is not known, of
    every folder and module holding the package's Python files (``src`` of ``src/pkg/x.py``
    too), and the package's name."""
    installed = installed_modules(package)
    if installed is not None:
        return frozenset(n.split(".")[0] for n in installed) | {package.name}
    return frozenset(part for module in package.modules
                     for part in module.path.removesuffix(".py").split("/")) | {package.name}


def _made_elsewhere(receiver: ast.expr, index: Index, own: frozenset[str]) -> bool:
    """True for a local name bound once to what a class of another library than rclpy and
    the package makes (``arm = MoveItPy(...)``: ``arm.create_subscription()`` is no node's)."""
    value = _only_value(receiver, index) if isinstance(receiver, ast.Name) else None
    made = value.func if isinstance(value, ast.Call) else None
    qualified = index.qualified(made) if isinstance(made, (ast.Name, ast.Attribute)) else None
    return qualified is not None and qualified.split(".")[0] not in own | {"rclpy"} and \
        not (isinstance(made, ast.Name) and made.id in index.relative)


def _only_value(name: ast.Name, index: Index) -> ast.expr | None:
    """The value of the one ``name = value`` binding ``name`` in the function around it, when
    that function binds the name nowhere else (no parameter, loop or second assignment)."""
    function = index.enclosing_function(name)
    if function is None:
        return None
    arguments = function.args
    if any(a.arg == name.id for a in (*arguments.posonlyargs, *arguments.args,
                                      *arguments.kwonlyargs, arguments.vararg,
                                      arguments.kwarg) if a is not None):
        return None
    stores = [n for n in ast.walk(function) if isinstance(n, ast.Name) and n.id == name.id
              and not isinstance(n.ctx, ast.Load)]
    assigns = [n for n in ast.walk(function) if isinstance(n, ast.Assign) and
               len(n.targets) == 1 and n.targets[0] in stores]
    return assigns[0].value if len(stores) == 1 and len(assigns) == 1 else None


@per_package
def _method_calls(package: Package) -> tuple[tuple[PythonModule, ast.Call, str, Index], ...]:
    """``x.<method>(...)`` calls in the installed modules importing rclpy, of methods the
    module defines no function of its own for, with the method name (a dozen rules ask). A
    method a class of another module of the package defines counts only on ``self`` of a
    class deriving from rclpy's Node alone (``self._client_handler.create_client()`` may be
    the package's own)."""
    found = []
    trees = installed_trees(package)
    methods = {f.name for _, _, index in trees for cls in index.classes for f in cls.body
               if isinstance(f, (ast.FunctionDef, ast.AsyncFunctionDef))}
    for module, _, index in trees:
        if not any(i.top_level == "rclpy" for i in module.imports):
            continue
        found.extend((module, call, call.func.attr, index) for call in index.calls
                     if isinstance(call.func, ast.Attribute) and
                     not index.defines_function(call.func.attr) and
                     (call.func.attr not in methods or _on_node_self(call.func.value, index)))
    return tuple(found)


def _on_node_self(receiver: ast.expr, index: Index) -> bool:
    """True for ``self`` in a method of a class deriving from rclpy's Node alone."""
    cls = index.enclosing_class(receiver)
    return isinstance(receiver, ast.Name) and receiver.id == "self" and cls is not None and \
        derives_from_node_alone(cls, index)


def not_from_rclpy(receiver: ast.expr, index: Index) -> bool:
    """True when ``receiver`` is certainly no rclpy node: an imported name, or what calling one
    makes, from a module other than rclpy (``boto3.session.Session().create_client(...)``),
    or from the package itself (``from .. import backend``: ``backend.create_publisher()``)."""
    made = receiver.func if isinstance(receiver, ast.Call) else receiver
    if isinstance(made, ast.Name) and made.id in index.relative:
        return True
    qualified = index.qualified(made) if isinstance(made, (ast.Name, ast.Attribute)) else None
    return qualified is not None and qualified.split(".")[0] != "rclpy"


def qos_calls(package: Package) -> Iterator[tuple[PythonModule, ast.Call, str]]:
    """Calls of the methods taking a ``qos_profile`` (publishers, subscriptions) whose
    arguments are all known (no ``*args`` or ``**kwargs``), with the method name."""
    for module, call, method, _ in node_api_calls(package):
        if "qos_profile" in PARAMETERS[method] and not unpacks(call):
            yield module, call, method


def argument(call: ast.Call, parameters: tuple[str, ...], name: str) -> ast.expr | None:
    """The expression passed for parameter ``name`` (positionally or by keyword), if known;
    a ``name`` not among the positional ``parameters`` is keyword-only."""
    keyword = next((k.value for k in call.keywords if k.arg == name), None)
    if keyword is not None or name not in parameters:
        return keyword
    position = parameters.index(name)
    positional = [a for a in call.args if not isinstance(a, ast.Starred)]
    return positional[position] if position < len(positional) and \
        len(positional) == len(call.args) else None


def literal_type(value: ast.expr) -> str | None:
    """The type a literal builds (``str`` for ``'a'`` and f-strings, ``int`` for ``-1``,
    ``NoneType``, ``list`` for a list display, ...); None for anything else."""
    if isinstance(value, ast.UnaryOp) and isinstance(value.op, (ast.USub, ast.UAdd)) and \
            isinstance(value.operand, ast.Constant):
        value = value.operand
    if isinstance(value, ast.Constant):
        return type(value.value).__name__
    return _DISPLAYS.get(type(value))


def unpacks(call: ast.Call) -> bool:
    """True when the call passes ``*args`` or ``**kwargs`` (its arguments are unknown)."""
    return any(isinstance(a, ast.Starred) for a in call.args) or \
        any(k.arg is None for k in call.keywords)


def name_argument(call: ast.Call) -> ast.expr | None:
    """The node name given to a Node constructor call, if any."""
    keyword = next((k.value for k in call.keywords if k.arg == "node_name"), None)
    first = call.args[0] if call.args and not isinstance(call.args[0], ast.Starred) else None
    return keyword or first


def bases_are_nodes(cls: ast.ClassDef, index: Index) -> bool:
    """True when every base of ``cls`` is one of rclpy's node classes (also for no base)."""
    return all(index.qualified(b) in NODE_CLASSES for b in cls.bases)


def derives_from_node_alone(cls: ast.ClassDef, index: Index) -> bool:
    """True for ``class X(Node)`` (``rclpy.node.Node``, its one base, no metaclass)."""
    return len(cls.bases) == 1 and not cls.keywords and \
        index.qualified(cls.bases[0]) == "rclpy.node.Node"


@per_tree
def node_subclasses(index: Index) -> tuple[ast.ClassDef, ...]:
    """Classes of the module derived from rclpy's node classes (directly or through others),
    worked out once per module (a dozen rules ask)."""
    found: list[ast.ClassDef] = []
    grew = True
    while grew:
        names = {c.name for c in found}
        more = [c for c in index.classes if c not in found and any(
            index.qualified(b) in NODE_CLASSES or
            isinstance(b, ast.Name) and b.id in names for b in c.bases)]
        found.extend(more)
        grew = bool(more)
    return tuple(found)


def node_constructions(index: Index) -> Iterator[ast.Call]:
    """``super().__init__(...)`` calls in Node subclasses, and Node/create_node calls."""
    node_classes = {id(c) for c in index.classes
                    if any(index.qualified(b) in NODE_CLASSES for b in c.bases)}
    for call in index.calls:
        if is_super_init(call) and id(index.enclosing_class(call)) in node_classes:
            yield call
    yield from (c for c in index.calls if index.qualified(c.func) in NODE_CLASSES)


def spin_cause(where: Span) -> str:
    """The root cause "the node is spun inside its own callback here": PYC035 states it; a
    missing timeout there (PYC005) is its consequence (a timeout would not mend the call)."""
    return f"spins-inside-callback:{where.path}:{where.line}:{where.col}"


_TYPE_KINDS = {"msg_type": "message", "srv_type": "service"}
"""What the type parameter of the create_* methods takes, by its name."""
_SERVED = frozenset({"create_subscription", "create_service"})
"""The creators whose third argument is the callback."""


def _method_of_class(value: ast.expr, call: ast.Call, index: Index) -> bool:
    """True for a lambda, or ``self.<a method of the class around the call>`` (plain: no
    decorator but ``staticmethod`` or ``classmethod``; a ``@property`` reads as its value)."""
    if isinstance(value, ast.Lambda):
        return True
    around = index.enclosing_class(call)
    if around is None or not (isinstance(value, ast.Attribute) and
                              isinstance(value.value, ast.Name) and value.value.id == "self"):
        return False
    named = [f for f in around.body
             if isinstance(f, (ast.FunctionDef, ast.AsyncFunctionDef)) and f.name == value.attr]
    return bool(named) and all(plainly_decorated(f) for f in named)


def swapped_argument(call: ast.Call, method: str, index: Index) -> tuple[ast.expr, str] | None:
    """The misplaced argument of ``call`` and what is wrong, or None."""
    first = call.args[0] if call.args else None
    second = call.args[1] if len(call.args) > 1 else None
    if method == "create_timer":
        third = call.args[2] if len(call.args) > 2 else None
        if third is not None and literal_type(third) in ("int", "float"):
            return third, ("a number is given where the callback group goes (a timer takes no "
                           "QoS depth: `'int' object has no attribute 'add_entity'`)")
        return (first, "the callback is given where the period goes (the period comes "
                "first)") if first is not None and _method_of_class(first, call, index) else None
    kind = _TYPE_KINDS[PARAMETERS[method][0]]
    if first is not None and literal_type(first) == "str":
        return first, (f"a string is given where the {kind} type goes (the type comes "
                       "first, then the name: ROS 1 had them the other way round)")
    if second is not None and INTERFACE.fullmatch(index.qualified(second) or ""):
        return second, (f"the {kind} type is given where the name goes (the type comes "
                        "first: ROS 1 had them the other way round)")
    if method in _SERVED and second is not None and _method_of_class(second, call, index):
        return second, ("the callback is given where the name goes (the type comes first, "
                        "then the name, then the callback)")
    return None
