"""Expressions that certainly hold a fresh instance of a known message class (PYC019), or
another object a call certainly makes (a publisher, PYC020).

A local variable holds one when its scope (a function, or the module) binds it exactly once,
``msg = String()``, and nothing in the scope or inside it binds the name otherwise (no
parameter, no second assignment, no ``for``/``with``/``del``/``global``/``nonlocal``, no
nested function's parameter or variable): every ``msg`` in the scope is that instance.
``self.x`` holds one in the methods of a class whose methods all assign ``self.x`` from
the same message constructor (``self.x = Twist()``, one target; ``self.x = None`` as a
placeholder aside), when nothing else in the module stores an attribute ``x``, no ``setattr``
could, and the class body defines no ``x``.
A parameter of a callback holds one when the module registers the function (``self.cb`` a
plain method of the class registering it, or a plain function bound once in the module) only
with known interfaces that agree: a subscription's message, a service's request and response,
an action server's goal (``goal_handle.request`` of the execute callback's goal handle, the
goal callback's argument); the function must never rebind the name.
"""

from __future__ import annotations

import ast
from collections import Counter
from collections.abc import Callable, Iterator, Mapping
from typing import Any, Generic, TypeVar

from pkgtool.knowledge.message_fields import Message, message_of, nested_message
from pkgtool.model.ast_nodes import nodes_of, nodes_of_class, subtree
from pkgtool.model.memo import per_package, per_tree
from pkgtool.model.package import Package
from pkgtool.records import record
from pkgtool.rules.node_api import ACTION_SERVER_CALLBACKS, ACTION_SERVERS, PARAMETERS, argument
from pkgtool.rules.scopes import BINDERS, scope_bindings
from pkgtool.rules.syntax_trees import FUNCTIONS, Index, installed_trees

Known = Callable[[ast.expr], Message | None]
"""The known message class a constructor's callee stands for, or None."""
T = TypeVar("T")
R = TypeVar("R")
Maker = Callable[[ast.Call], T | None]
"""What a call certainly makes (a known message, a publisher), or None."""


@record
class Instance(Generic[T]):
    """Where an object (``message``: a known message or what else a maker makes) is used:
    ``uses`` are the attributes read or stored on it (``msg.data``, ``self.msg.data``),
    ``refs`` the expressions reading the object itself (``msg``, ``self.msg``) and ``stored``
    the attribute paths assigned anywhere below it (``("header", "stamp")`` for
    ``msg.header.stamp = ...``)."""

    message: T
    uses: list[ast.Attribute]
    stored: frozenset[tuple[str, ...]]
    refs: list[ast.expr]


@record
class _Names:
    """What a scope and every scope inside it do with names: how often each name is bound
    (``counts``: parameters, targets, imports, definitions, ``global``/``nonlocal`` names),
    by name the attributes taken on it (``uses``) and its reads (``refs``), and by (name,
    attribute) the attributes taken on ``name.attribute`` (``deeper``), each in walk order."""

    counts: Counter[str]
    uses: dict[str, list[ast.Attribute]]
    refs: dict[str, list[ast.expr]]
    deeper: dict[tuple[str, str], list[ast.Attribute]]


def _bind(node: ast.AST, found: Counter[str]) -> None:
    """Count the names a binding node (other than a name, an argument) binds."""
    if isinstance(node, (*FUNCTIONS, ast.ClassDef)):
        found[node.name] += 1
    elif isinstance(node, (ast.Import, ast.ImportFrom)):
        found.update((a.asname or a.name).split(".")[0] for a in node.names)
    elif isinstance(node, (ast.ExceptHandler, ast.MatchAs, ast.MatchStar)) and node.name:
        found[node.name] += 1
    elif isinstance(node, ast.MatchMapping) and node.rest:
        found[node.rest] += 1
    elif isinstance(node, (ast.Global, ast.Nonlocal)):
        found.update(node.names * 2)


@per_tree
def _names(node: ast.AST) -> _Names:
    """The :class:`_Names` of ``node`` and every node inside it (a function's own name
    included), in one walk, once per node: several rules ask about the same functions."""
    found = _Names(Counter(), {}, {}, {})
    counts, uses, refs, deeper = found.counts, found.uses, found.refs, found.deeper
    for current in nodes_of(node) if isinstance(node, ast.Module) else subtree(node):
        if isinstance(current, ast.Attribute):
            value = current.value
            if isinstance(value, ast.Name):
                uses.setdefault(value.id, []).append(current)
            elif isinstance(value, ast.Attribute) and isinstance(value.value, ast.Name):
                deeper.setdefault((value.value.id, value.attr), []).append(current)
        elif isinstance(current, ast.Name):
            if isinstance(current.ctx, ast.Load):
                refs.setdefault(current.id, []).append(current)
            else:
                counts[current.id] += 1
        elif isinstance(current, ast.arg):
            counts[current.arg] += 1
        elif type(current) in BINDERS:
            _bind(current, counts)
    return found


def binding_counts(node: ast.AST) -> Counter[str]:
    """How many times each name is bound anywhere in ``node`` (nested scopes, parameters and
    the function's own name included; ``global``/``nonlocal`` count twice): computed once
    per node with the rest of its :class:`_Names`. Treat as read-only."""
    return _names(node).counts


def _path(node: ast.Attribute) -> tuple[str, ...]:
    """The attribute names of ``node`` after its root: ``("header", "stamp")`` for
    ``msg.header.stamp``."""
    names: list[str] = []
    current: ast.expr = node
    while isinstance(current, ast.Attribute):
        names.append(current.attr)
        current = current.value
    return tuple(reversed(names))


def instance_of(message: T, uses: list[ast.Attribute], refs: list[ast.expr], index: Index,
                skip: int = 0) -> Instance[T]:
    """The instance used by ``uses``: the paths stored under it (the first ``skip`` names of
    each path are the way to the instance itself)."""
    stored = set()
    for use in uses:
        top: ast.AST = use
        while isinstance(index.parents.get(id(top)), ast.Attribute):
            top = index.parents[id(top)]
        if isinstance(top, ast.Attribute) and not isinstance(top.ctx, ast.Load):
            stored.add(_path(top)[skip:])
    return Instance(message, uses, frozenset(stored), refs)


def _fresh(node: ast.AST) -> tuple[str, ast.Call] | None:
    """(name, call) of an assignment ``name = call(...)`` to one name."""
    if isinstance(node, ast.Assign) and len(node.targets) == 1 \
            and isinstance(node.targets[0], ast.Name) and isinstance(node.value, ast.Call):
        return node.targets[0].id, node.value
    return None


Scope = ast.Module | ast.FunctionDef | ast.AsyncFunctionDef


@per_tree
def _facts(tree: ast.AST) -> dict[object, Any]:
    """What the rules derive from ``tree`` by key (its message instances): worked out once
    per tree (PYC019, PYC020 and PYC023-PYC026 read the same)."""
    return {}


def kept(tree: ast.AST, key: object, work_out: Callable[[], R]) -> R:
    """``work_out()``, kept with ``tree`` (or a part of one) under ``key`` (see
    :func:`_facts`)."""
    known = _facts(tree)
    if key not in known:
        known[key] = work_out()
    found: R = known[key]
    return found


def local_instances(tree: ast.Module, index: Index, make: Maker[T]) -> Iterator[Instance[T]]:
    """Local variables (of functions and of the module) that hold what ``make`` makes: the
    scope's assignments of the same thing (``result = Turn.Result()`` in each branch) are
    then the only bindings of the name in the scope and inside it (the scope's own bindings
    are among those counted: no need to count them apart)."""
    made: dict[int, tuple[Scope, dict[str, list[T]]]] = {}
    for node in nodes_of_class(tree, ast.Assign):
        fresh = _fresh(node)
        message = make(fresh[1]) if fresh is not None else None
        scope = _scope(node, tree, index) if message is not None else None
        if fresh is not None and message is not None and scope is not None:
            made.setdefault(id(scope), (scope, {}))[1].setdefault(fresh[0], []).append(message)
    for scope, found in made.values():
        names = _names(scope)
        for name, messages in found.items():
            if names.counts[name] == len(messages) and messages.count(messages[0]) == len(
                    messages):
                yield instance_of(messages[0], names.uses.get(name, []),
                                  names.refs.get(name, []), index)


def _scope(statement: ast.AST, tree: ast.Module, index: Index) -> Scope | None:
    """The function whose own body holds ``statement``, ``tree`` at module level, None in a
    class body."""
    parent = index.parents.get(id(statement))
    while parent is not None and not isinstance(parent, (*FUNCTIONS, ast.ClassDef)):
        parent = index.parents.get(id(parent))
    if isinstance(parent, ast.ClassDef):
        return None
    return parent if isinstance(parent, FUNCTIONS) else tree


_INSTANCE_DECORATORS = frozenset({"property", "cached_property", "setter", "getter",
                                  "deleter"})
"""Decorators of methods still called with the instance first (``@property``,
``@x.setter``, ``@functools.cached_property``)."""


def method_receiver(method: ast.AST) -> str | None:
    """The first parameter of a plain method (no decorator but a property's), when the
    method never rebinds it."""
    if not isinstance(method, FUNCTIONS) or any(
            (d.id if isinstance(d, ast.Name) else d.attr if isinstance(d, ast.Attribute)
             else "") not in _INSTANCE_DECORATORS for d in method.decorator_list):
        return None
    positional = [*method.args.posonlyargs, *method.args.args]
    if not positional or _names(method).counts[positional[0].arg] != 1 or \
            positional[0].arg != "self" or _annotated_otherwise(positional[0], method):
        return None
    return positional[0].arg


def _annotated_otherwise(first: ast.arg, method: ast.FunctionDef | ast.AsyncFunctionDef
                         ) -> bool:
    """True when the first parameter is annotated with a class (``pt: JointTrajectoryPoint``)
    and is not ``self``/``cls``: a method missing its ``self``, whose first parameter the
    author meant as that class, not the instance."""
    note = first.annotation
    return note is not None and first.arg not in ("self", "cls") and \
        not (isinstance(note, ast.Name) and note.id == "Self")


def fields_taken(instance: Instance[Message], index: Index
                 ) -> Iterator[tuple[ast.Attribute, Message, tuple[str, ...]]]:
    """Down each use of a message instance (``msg.pose.position.x``), every attribute taken
    with the message it is taken on and its path from the instance (``("pose", "position")``),
    while that message is certain: not past a private name, an attribute the message lacks
    (yielded, then the walk stops) or a field the code assigns (``msg.pose = ...``)."""
    for use in instance.uses:
        node: ast.AST = use
        message: Message | None = instance.message
        path: tuple[str, ...] = ()
        while isinstance(node, ast.Attribute) and message is not None and \
                not node.attr.startswith("_"):
            path = (*path, node.attr)
            yield node, message, path
            if not message.has(node.attr):
                break
            message = None if path in instance.stored else nested_message(message, node.attr)
            parent = index.parents.get(id(node))
            if not (isinstance(parent, ast.Attribute) and parent.value is node):
                break
            node = parent


def name_reads(scope: ast.AST, name: str) -> list[ast.expr]:
    """The reads of ``name`` itself in ``scope`` and every scope inside it, in walk order."""
    return _names(scope).refs.get(name, [])


def attributes_taken(scope: ast.AST, name: str) -> list[ast.Attribute]:
    """The attributes taken on ``name`` (``name.x``, read or stored) in ``scope`` and every
    scope inside it, in walk order (from the scope's one walk for its names)."""
    return _names(scope).uses.get(name, [])


@record
class _ClassFacts:
    """The ``self.x`` attributes of a class's methods: by name the stores (in order), the
    reads of ``self.x`` itself (``refs``) and the attributes taken on it (``uses``), and the
    names the class body binds (``defined``)."""

    stores: dict[str, list[ast.Attribute]]
    refs: dict[str, list[ast.expr]]
    uses: dict[str, list[ast.Attribute]]
    defined: Counter[str]


@per_tree
def _class_facts(cls: ast.ClassDef) -> _ClassFacts:
    """The :class:`_ClassFacts` of ``cls``, from its methods' :func:`_names`, once per class
    (PYC019, PYC020 and the callback lookup read the same)."""
    stores: dict[str, list[ast.Attribute]] = {}
    refs: dict[str, list[ast.expr]] = {}
    uses: dict[str, list[ast.Attribute]] = {}
    for method in cls.body:
        receiver = method_receiver(method)
        if receiver is None:
            continue
        names = _names(method)
        for node in names.uses.get(receiver, []):
            if isinstance(node.ctx, ast.Load):
                refs.setdefault(node.attr, []).append(node)
            else:
                stores.setdefault(node.attr, []).append(node)
        for (root, attr), deeper in names.deeper.items():
            if root == receiver:
                uses.setdefault(attr, []).extend(deeper)
    return _ClassFacts(stores, refs, uses, scope_bindings(cls))


@per_tree
def _stored_attributes(tree: ast.Module) -> Counter[str] | None:
    """How often the module stores each attribute name, once per tree (PYC019 and PYC020 ask);
    None when it calls ``setattr``, ``delattr`` or ``exec`` (any attribute may change)."""
    if any(isinstance(n, ast.Call) and isinstance(n.func, ast.Name) and
           n.func.id in ("setattr", "delattr", "exec") for n in nodes_of_class(tree, ast.Call)):
        return None
    return Counter(n.attr for n in nodes_of_class(tree, ast.Attribute)
                   if isinstance(n, ast.Attribute) and not isinstance(n.ctx, ast.Load))


def attribute_instances(tree: ast.Module, index: Index, make: Maker[T],
                        held: Mapping[int, T] | None = None) -> Iterator[Instance[T]]:
    """``self.x`` attributes of classes that always assign them what ``make`` makes, or a name
    that ``held`` (by id of the name node) knows to hold one (a callback's message)."""
    stores = _stored_attributes(tree)
    held = held or {}
    if stores is None or not any(
            len(node.targets) == 1 and isinstance(node.targets[0], ast.Attribute) and (
                isinstance(node.value, ast.Call) and make(node.value) is not None or
                id(node.value) in held)
            for node in nodes_of_class(tree, ast.Assign)):  # type: ignore[attr-defined]
        return
    for cls in index.classes:
        facts = _class_facts(cls)
        for attr, targets in facts.stores.items():
            made = [_assigned(target, index, make, held) for target in targets
                    if not _assigned_none(target, index)]
            if (made and made[0] is not None and made.count(made[0]) == len(made)
                    and len(targets) == stores[attr] and not facts.defined[attr]):
                yield instance_of(made[0], facts.uses.get(attr, []), facts.refs.get(attr, []),
                                  index, skip=1)


def _assigned_none(target: ast.Attribute, index: Index) -> bool:
    """True for ``target = None`` (the only target): a placeholder until the object is made
    (using it before then fails anyway)."""
    parent = index.parents.get(id(target))
    return isinstance(parent, ast.Assign) and parent.targets == [target] and \
        isinstance(parent.value, ast.Constant) and parent.value.value is None


def _assigned(target: ast.Attribute, index: Index, make: Maker[T], held: Mapping[int, T]
              ) -> T | None:
    """What ``target = call(...)`` (the only target) assigns, as ``make`` knows, or
    ``target = name`` as ``held`` knows; else None."""
    parent = index.parents.get(id(target))
    if not (isinstance(parent, ast.Assign) and parent.targets == [target]):
        return None
    if isinstance(parent.value, ast.Call):
        return make(parent.value)
    return held.get(id(parent.value)) if isinstance(parent.value, ast.Name) else None


Function = ast.FunctionDef | ast.AsyncFunctionDef
_Parameter = tuple[int, int, str | None]
"""A callback parameter: (id of the function, position among its parameters after any
receiver, the attribute the message is read through: ``request`` of a goal handle)."""


def _registrations(index: Index, known: Known
                   ) -> Iterator[tuple[ast.expr, list[tuple[Message | None, str | None]]]]:
    """(callback expression, for each leading parameter the message it receives and the
    attribute it is reached through) of subscriptions, services and action servers."""
    for call in index.calls:
        method = call.func.attr if isinstance(call.func, ast.Attribute) else ""
        if method == "create_subscription" and not any(k.arg == "raw" for k in call.keywords):
            kind = argument(call, PARAMETERS[method], "msg_type")
            callback = argument(call, PARAMETERS[method], "callback")
            parts: list[tuple[ast.expr | None, str | None]] = [(kind, None)]
        elif method == "create_service":
            kind = argument(call, PARAMETERS[method], "srv_type")
            callback = argument(call, PARAMETERS[method], "callback")
            parts = [(companion(kind, "Request"), None), (companion(kind, "Response"), None)]
        elif index.qualified(call.func) in ACTION_SERVERS:
            kind = argument(call, ACTION_SERVER_CALLBACKS[0], "action_type")
            callback = argument(call, ACTION_SERVER_CALLBACKS[0], "execute_callback")
            parts = [(companion(kind, "Goal"), "request")]
            judge = argument(call, ACTION_SERVER_CALLBACKS[0], "goal_callback")
            if judge is not None:  # it gets the goal itself
                yield judge, [(known(e) if e is not None else None, None)
                              for e in (companion(kind, "Goal"),)]
        else:
            continue
        if callback is not None:
            yield callback, [(known(e) if e is not None else None, via) for e, via in parts]


def companion(kind: ast.expr | None, name: str) -> ast.expr | None:
    """``kind.<name>`` (``Trigger.Request``), or None without a ``kind``."""
    return None if kind is None else ast.Attribute(value=kind, attr=name, ctx=ast.Load())


def _plain(definitions: list[Function], bindings: int) -> Function | None:
    """The one definition when it is a function without decorators and its name's only
    binding (``bindings``: how often the name is bound where it is defined)."""
    if len(definitions) == bindings == 1 and not definitions[0].decorator_list:
        return definitions[0]
    return None


def callback_function(expr: ast.expr, tree: ast.Module, index: Index
                      ) -> tuple[Function, int] | None:
    """The function a callback expression certainly names, and how many leading parameters
    are not the callback's arguments (1 for a method's receiver)."""
    if isinstance(expr, ast.Name):
        found = _plain([f for f in index.functions if f.name == expr.id],
                       _names(tree).counts[expr.id])
        outside = found is not None and not isinstance(index.parents.get(id(found)), ast.ClassDef)
        return (found, 0) if outside and found is not None else None
    cls, caller = index.enclosing_class(expr), index.enclosing_function(expr)
    if not (isinstance(expr, ast.Attribute) and isinstance(expr.value, ast.Name) and cls
            and caller in cls.body and method_receiver(caller) == expr.value.id):
        return None
    found = _plain([s for s in cls.body if isinstance(s, FUNCTIONS) and s.name == expr.attr],
                   scope_bindings(cls)[expr.attr])
    return (found, 1) if found is not None else None


def callback_instances(tree: ast.Module, index: Index, known: Known
                       ) -> Iterator[Instance[Message]]:
    """Callback parameters that certainly receive a known message (see the module's doc)."""
    received: dict[_Parameter, dict[str | None, Message | None]] = {}
    functions: dict[int, tuple[Function, list[str]]] = {}
    for expr, parts in _registrations(index, known):
        found = callback_function(expr, tree, index)
        if found is None:
            continue
        function, skip = found
        arguments = function.args
        names = [a.arg for a in [*arguments.posonlyargs, *arguments.args][skip:]]
        functions[id(function)] = (function, names)
        for position, (message, via) in enumerate(parts):
            kept = received.setdefault((id(function), position, via), {})
            kept[message.name if message is not None else None] = message
    for (key, position, via), messages in received.items():
        function, parameters = functions[key]
        message = next(iter(messages.values())) if len(messages) == 1 else None
        if message is None or position >= len(parameters):
            continue
        yield from parameter_instance(tree, function, parameters[position], message, via,
                                      index)


def parameter_instance(tree: ast.Module, function: Function, name: str, message: Message,
                       via: str | None, index: Index) -> Iterator[Instance[Message]]:
    """The instance a parameter holds (or holds at ``name.<via>``) when never rebound."""
    facts = _names(function)
    if facts.counts[name] != 1:
        return
    uses = facts.uses.get(name, [])
    if via is None:
        yield instance_of(message, uses, facts.refs.get(name, []), index)
        return
    refs: list[ast.expr] = [use for use in uses if use.attr == via]
    deeper = [parent for ref in refs if isinstance(parent := index.parents.get(id(ref)),
                                                   ast.Attribute) and parent.value is ref]
    yield instance_of(message, deeper, refs, index, skip=1)


@per_package
def _rospy_indexes(package: Package) -> frozenset[int]:
    """Ids of the indexes of the installed modules that import rospy unguarded (ROS 1 code),
    worked out once per package (every message rule asks, module by module)."""
    return frozenset(id(index) for module, _, index in installed_trees(package)
                     if any(imported.top_level == "rospy" and not imported.guarded
                            for imported in module.imports))


def known_messages(package: Package, index: Index, distro: str | None = None) -> Known:
    """What a callee stands for: a message class of a package the table speaks for on
    ``distro`` (the target's when None), or one a package of the workspace defines in its own
    interface files (a workspace package of a name the table knows is never the table's);
    nothing in a ROS 1 package, nor in a module importing rospy unguarded in a project without
    package.xml (ROS 1's messages: a stamp is a ``rospy.Time``)."""
    manifest = package.manifest
    ros1 = manifest.is_ros1 if manifest is not None else id(index) in _rospy_indexes(package)
    distro = distro or package.context.distro

    def known(func: ast.expr) -> Message | None:
        dotted = index.qualified(func)
        if ros1 or dotted is None:
            return None
        sibling = package.context.workspace.get(dotted.split(".")[0])
        return message_of(dotted, distro, None if sibling is None else sibling.messages)
    return known
