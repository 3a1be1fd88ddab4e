"""PYC034: a blocking wait that the node's executor can never end: ``rate.sleep()`` where
nothing spins the node, ``client.call()`` in a callback of the client's own group, the node
spun from its own callback."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.imports import entry_points_installed
from pkgtool.rules.node_api import SPINS, node_subclasses, spin_cause, unpacks
from pkgtool.rules.python._callbacks import callback_arguments
from pkgtool.rules.python._message_instances import (
    binding_counts, callback_function, method_receiver)
from pkgtool.rules.registry import rule
from pkgtool.rules.scopes import scope_walk
from pkgtool.rules.syntax_trees import FUNCTIONS, Index, installed_trees

_THREADS = frozenset({"threading", "_thread", "concurrent", "multiprocessing", "asyncio"})
"""Modules through which code may spin a node in another thread (or process, or loop)."""
Function = ast.FunctionDef | ast.AsyncFunctionDef
_SERVED = frozenset({"create_timer()", "create_subscription()", "create_service()"})
"""The APIs whose callbacks run in the callback group the call names (the node's default,
mutually exclusive one when it names none)."""
_GROUP = "callback_group"
_MULTI_THREADED_NAMES = frozenset({"MultiThreadedExecutor"})
_MULTI_THREADED = frozenset({"rclpy.executors.MultiThreadedExecutor"})
"""The executor that runs a Rate's timer while a callback sleeps on it."""


def _spin_handed_over(call: ast.Call) -> bool:
    """True for a call handing a spin function over to run (``Thread(target=rclpy.spin,
    args=(node,))``, ``pool.submit(executor.spin)``), however the thread class was imported
    (a star import may bring ``threading``)."""
    values = [*call.args, *(k.value for k in call.keywords)]
    return any(isinstance(v, ast.Attribute) and v.attr in _SPIN_NAMES or
               isinstance(v, ast.Name) and v.id in _SPIN_NAMES for v in values)


_SPIN_NAMES = frozenset({"spin", "spin_once", "spin_until_future_complete"})


def _rate_made(value: ast.expr | None) -> bool:
    """True for a call ``<x>.create_rate(...)``."""
    return isinstance(value, ast.Call) and isinstance(value.func, ast.Attribute) and \
        value.func.attr == "create_rate"


def _stored(target: ast.expr) -> str | None:
    """``r`` for a local ``r``, ``.r`` for an attribute ``self.r``; None for other targets."""
    return target.id if isinstance(target, ast.Name) else \
        f".{target.attr}" if isinstance(target, ast.Attribute) else None


def _sleeps(function: Function, attributes: frozenset[str] = frozenset()) -> Iterator[ast.Call]:
    """``r.sleep()`` calls of ``function`` on a Rate it makes itself (``r =
    x.create_rate(...)``, ``self.r = ...``, or ``x.create_rate(...).sleep()``), or on an
    attribute of ``attributes`` (``.r``: every ``self.r`` the module stores is a Rate); none
    when it spins anything (``rclpy.spin_once(self)`` before each sleep wakes the Rate)."""
    nodes = list(scope_walk(function.body))
    calls = [n for n in nodes if isinstance(n, ast.Call)]
    if any((c.func.attr if isinstance(c.func, ast.Attribute) else
            getattr(c.func, "id", "")).startswith("spin") for c in calls):
        return
    rates = attributes | {_stored(t) for n in nodes if isinstance(n, ast.Assign) and
                          _rate_made(n.value) for t in n.targets} - {None}
    for call in calls:
        func = call.func
        if isinstance(func, ast.Attribute) and func.attr == "sleep" and not call.args and \
                (_rate_made(func.value) or _stored(func.value) in rates):
            yield call


def _attribute_stores(tree: ast.Module, index: Index) -> dict[str, list[ast.expr | None]]:
    """By attribute name, what each store of the module assigns it (``self.x = value``, one
    target; None for any other store)."""
    stores: dict[str, list[ast.expr | None]] = {}
    for node in nodes_of_class(tree, ast.Attribute):
        if isinstance(node, ast.Attribute) and not isinstance(node.ctx, ast.Load):
            parent = index.parents.get(id(node))
            stores.setdefault(node.attr, []).append(
                parent.value if isinstance(parent, ast.Assign) and parent.targets == [node]
                else None)
    return stores


def _rate_attributes(tree: ast.Module, index: Index) -> frozenset[str]:
    """``.r`` for each attribute every store of which in the module is ``create_rate(...)``."""
    return frozenset(f".{name}" for name, values in _attribute_stores(tree, index).items()
                     if all(_rate_made(v) for v in values))


def _served_callbacks(package: Package) -> Iterator[tuple[str, Function, ast.Module, Index]]:
    """Functions registered (certainly) as the callback of a timer, subscription or service,
    in any callback group, with their file, tree and index."""
    for path, value, api, _, index, tree in callback_arguments(package):
        found = callback_function(value, tree, index) if api in _SERVED else None
        if found is not None:
            yield path, found[0], tree, index


def _default_group_callbacks(package: Package) -> Iterator[tuple[str, Function, Index]]:
    """Methods of a class deriving from rclpy's node classes registered by it
    (``self.create_timer(p, self.tick)``) as the callback of a timer, subscription or service
    in the node's default callback group (no ``callback_group=``, nor a timer's third
    argument), with their file and module index."""
    for path, value, api, _, index, tree in callback_arguments(package):
        call = index.parents.get(id(value))
        call = index.parents.get(id(call)) if isinstance(call, ast.keyword) else call
        if api not in _SERVED or not isinstance(call, ast.Call) or unpacks(call) or \
                any(k.arg == _GROUP for k in call.keywords) or \
                api == "create_timer()" and len(call.args) > 2 or \
                any(index.defines_function(made) for made in _MAKERS):
            continue  # a group given by position, or a class making entities its own way
        found = callback_function(value, tree, index)
        cls = index.enclosing_class(found[0]) if found is not None else None
        if found is not None and found[1] == 1 and cls is not None and \
                cls in node_subclasses(index):
            yield path, found[0], index


_MAKERS = ("create_client", "create_timer", "create_subscription", "create_service")
"""Node methods a class of the module may define itself (putting entities in groups of its
own, as ``simple_node``'s base class does)."""


def _default_group_clients(tree: ast.Module, index: Index) -> set[str]:
    """Attribute names every store of which in the module is a ``create_client(...)`` call
    naming no callback group (a client in the node's default group), or ``None``."""
    stores = _attribute_stores(tree, index)
    return {name for name, values in stores.items() if name != "_default_callback_group" and
            "_default_callback_group" not in stores and any(
                isinstance(v, ast.Call) for v in values) and all(
                isinstance(v, ast.Constant) and v.value is None or
                isinstance(v, ast.Call) and isinstance(v.func, ast.Attribute) and
                v.func.attr == "create_client" and not unpacks(v) and
                not any(k.arg == _GROUP for k in v.keywords) for v in values)}


def _other_groups(index: Index) -> bool:
    """True when the module names a callback group anywhere (``callback_group=``), or passes
    ``**kwargs`` to a call that may take one: some entity may be outside the default group."""
    return any(any(k.arg in (_GROUP, None) for k in c.keywords) for c in index.calls)


def _default_group_future(future: ast.expr | None, function: Function, clients: set[str],
                          index: Index) -> bool:
    """True when ``future`` is what ``self.<client>.call_async(...)`` returned, for a client
    of ``clients`` (the node's default group): the call itself, or a local name bound once,
    to it."""
    receiver = method_receiver(function)
    if isinstance(future, ast.Name):
        bound = [n for n in scope_walk(function.body) if isinstance(n, ast.Assign) and
                 any(isinstance(t, ast.Name) and t.id == future.id for t in n.targets)]
        future = bound[0].value if len(bound) == 1 and len(bound[0].targets) == 1 and \
            binding_counts(function)[future.id] == 1 else None
    return isinstance(future, ast.Call) and isinstance(future.func, ast.Attribute) and \
        future.func.attr == "call_async" and isinstance(future.func.value, ast.Attribute) and \
        future.func.value.attr in clients and isinstance(future.func.value.value, ast.Name) \
        and future.func.value.value.id == receiver


def _self_spins(function: Function, spins: list[ast.Call], clients: set[str], index: Index
                ) -> Iterator[ast.Call]:
    """``rclpy.spin_until_future_complete(self, future)`` for a ``future`` of a client in the
    node's default group (``clients``), or ``spin_once(self)``, ``spin(self)`` in a module
    that puts nothing in another group, in a method: the node spun from inside one of its
    own callbacks for what that callback's group keeps from running (``spins``: the
    module's calls of those functions)."""
    receiver = method_receiver(function)
    others: bool | None = None
    for node in spins:
        spun = node.args[0] if node.args else next(
            (k.value for k in node.keywords if k.arg == "node"), None)
        if not isinstance(spun, ast.Name) or spun.id != receiver or \
                index.enclosing_function(node) is not function:
            continue
        if index.qualified(node.func) == "rclpy.spin_until_future_complete":
            future = node.args[1] if len(node.args) > 1 else next(
                (k.value for k in node.keywords if k.arg == "future"), None)
            if _default_group_future(future, function, clients, index):
                yield node
        else:
            others = _other_groups(index) if others is None else others
            if not others:
                yield node


def _blocking_calls(function: Function, clients: set[str]) -> Iterator[ast.Call]:
    """``self.<client>.call(request)`` calls (no timeout) of a method on a client of
    ``clients``."""
    receiver = method_receiver(function)
    for node in scope_walk(function.body):
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and \
                node.func.attr == "call" and len(node.args) == 1 and not node.keywords and \
                isinstance(node.func.value, ast.Attribute) and \
                node.func.value.attr in clients and \
                isinstance(node.func.value.value, ast.Name) and \
                node.func.value.value.id == receiver:
            yield node


@rule("PYC034", "deadlocked-wait", Severity.ERROR,
      fix="Use a timer (`self.create_timer(period, self.step)`) instead of a loop; call "
          "services with `call_async()` and a done callback")
def deadlocked_wait(package: Package) -> Iterator[Hit]:
    """A blocking wait that the node's executor can never end: it never returns.

    ## What it does
    Reports `sleep()` on a Rate that `create_rate()` made in the same function, when that
    function is the `__init__` of a `Node` subclass or a console script's entry function,
    the function spins nothing itself (no `spin`, `spin_once`, ...), and no installed module
    of the package imports `threading`, `concurrent`, `multiprocessing`, `_thread` or
    `asyncio` (a thread may spin the node then, as in rclpy's own Rate example).

    Reports `self.client.call(request)` (no timeout) in a method that the class registers as
    the callback of a timer, subscription or service with no `callback_group=`, when every
    assignment of `client` in the module is a `create_client()` with no `callback_group=`
    either (and the module does not replace the node's `_default_callback_group`), and
    `rclpy.spin_until_future_complete(self, future)` in such a callback for the `future` of
    `call_async()` on such a client, or `rclpy.spin_once(self)`, `rclpy.spin(self)` there in
    a module that names no callback group: the node spun from inside its own callback for
    what its group keeps from running. (A client, subscription or timer in another group is
    served by the nested spin.)

    Reports `rate.sleep()` in a method registered as the callback of a timer, subscription
    or service (on a Rate the method makes, or a `self.rate` every store of which is a
    `create_rate()`), when no installed module uses the `MultiThreadedExecutor` or threads.

    ## Why is this bad?
    rclpy's `Rate` sleeps until a timer of its node fires, and a timer fires only while an
    executor spins the node. In `__init__` the node cannot be spinning yet, and in `main`
    before `rclpy.spin()` nothing spins it: the first `rate.sleep()` blocks until ROS shuts
    down, with no error; the node does nothing (checked on Jazzy).

    `Client.call()` waits until the executor hands the client its response, but the
    executor runs nothing else of a mutually exclusive callback group while one of its
    callbacks runs, and both are in the node's default group: the callback waits forever,
    whatever the executor (checked on Jazzy; rclpy's documentation calls it a deadlock).
    Spinning the node again from its own callback does not deliver it either: it returns at
    its timeout with no result, under the single- and the multi-threaded executor alike
    (checked on Jazzy); without a timeout it never returns.
    A Rate wakes when its own timer runs, and the single-threaded executor (the one
    `rclpy.spin()` uses) runs one callback at a time: a callback sleeping on a Rate keeps
    that timer from ever running (rclpy's `Rate.sleep()` documents it).

    ## Example
    ```python
    def __init__(self):
        super().__init__('talker')
        rate = self.create_rate(10)
        while rclpy.ok():
            self.publish()
            rate.sleep()
    ```

    ## Use instead
    ```python
    def __init__(self):
        super().__init__('talker')
        self.timer = self.create_timer(0.1, self.publish)
    ```
    """
    trees = installed_trees(package)
    clients = {m.path: _default_group_clients(t, i) for m, t, i in trees}
    spins = {m.path: [c for c in i.calls if i.qualified(c.func) in SPINS] for m, _, i in trees}
    for path, function, index in _default_group_callbacks(package):
        served = clients.get(path, set())
        for call in _blocking_calls(function, served) if served else ():
            yield Hit(Span(path, call.lineno, call.col_offset + 1),
                      f"`{ast.unparse(call)}` waits in a callback for a response that the "
                      "executor hands over only after the callback ends (both are in the "
                      "node's default callback group): it never returns")
        for call in _self_spins(function, spins.get(path, []), served, index):
            where = Span(path, call.lineno, call.col_offset + 1)
            yield Hit(where, f"`{ast.unparse(call.func)}({method_receiver(function)}, ...)` "
                             f"spins the node inside its own callback `{function.name}`: what "
                             "it waits for is never delivered (given a timeout it returns "
                             "with nothing done; without one it blocks for good)",
                      cause=spin_cause(where))
    if any(i.top_level in _THREADS for module, _, _ in trees for i in module.imports) or \
            any(_spin_handed_over(call) for _, _, i in trees for call in i.calls):
        return
    if not any(i.qualified(n) in _MULTI_THREADED for _, _, i in trees for n in i.attributes) \
            and not any(f.module == "rclpy.executors" and any(
                a.name in _MULTI_THREADED_NAMES for a in f.names)
                for _, _, i in trees for f in i.import_froms):
        seen: set[int] = set()
        rates = {m.path: _rate_attributes(t, i) for m, t, i in trees
                 if any(isinstance(c.func, ast.Attribute) and c.func.attr == "create_rate"
                        for c in i.calls)}
        for path, function, _, _ in _served_callbacks(package) if rates else ():
            for call in _sleeps(function, rates.get(path, frozenset())):
                if id(call) not in seen:
                    seen.add(id(call))
                    yield Hit(Span(path, call.lineno, call.col_offset + 1),
                              f"`{ast.unparse(call)}` in the callback `{function.name}` waits "
                              "for the Rate's timer, which the single-threaded executor runs "
                              "only after this callback returns: it never returns")
    entries = {(path, entry.attr) for entry, path in
               entry_points_installed(package, "console_scripts") if entry.valid}
    for module, tree, index in trees:
        if not any(isinstance(c.func, ast.Attribute) and c.func.attr == "create_rate"
                   for c in index.calls):
            continue  # no Rate made here: nothing to sleep on
        functions = [f for cls in node_subclasses(index) for f in cls.body
                     if isinstance(f, FUNCTIONS) and f.name == "__init__"]
        functions += [f for f in tree.body if isinstance(f, FUNCTIONS) and
                      (module.path, f.name) in entries]
        for function in functions:
            for call in _sleeps(function):
                yield Hit(Span(module.path, call.lineno, call.col_offset + 1),
                          f"`{ast.unparse(call)}` waits for a timer of the node, which fires "
                          "only while the node spins, and nothing spins it here"
                          f"{' (in `__init__`)' if function.name == '__init__' else ''}: "
                          "it never returns")
