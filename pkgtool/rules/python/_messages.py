"""Every instance of a known message a module certainly holds: the fresh ones and callback
parameters :mod:`._message_instances` finds, and the responses of service calls.

A service response is what ``future.result()`` gives when the future is certainly a client's
``call_async()`` (a local name or ``self.x`` only ever assigned one, or None; the future a
done callback registered on one gets) and the client certainly one of a known service
(``self.create_client(AddTwoInts, ...)``, assigned the same way, in the same module).
"""

from __future__ import annotations

import ast

from pkgtool.knowledge.message_fields import Message
from pkgtool.model.package import Package
from pkgtool.rules.node_api import PARAMETERS, argument
from pkgtool.rules.python._annotated_messages import annotated_instances
from pkgtool.rules.python._assignments import (assigned_values, done_callback_futures,
                                               is_none)
from pkgtool.rules.python._message_instances import (Instance, Known, attribute_instances,
                                                     callback_instances, companion, kept,
                                                     local_instances)
from pkgtool.rules.syntax_trees import Index

_DEPTH = 3
"""How many done callbacks deep a future is followed (a callback registering another)."""


def _made_by(value: ast.expr, method: str) -> bool:
    """True for a call ``<x>.<method>(...)``."""
    return isinstance(value, ast.Call) and isinstance(value.func, ast.Attribute) and \
        value.func.attr == method


def _calls(value: ast.expr, method: str, package: Package, tree: ast.Module, index: Index
           ) -> list[ast.Call] | None:
    """The ``<x>.<method>(...)`` calls of this module ``value`` certainly holds the result of
    (None aside), or None."""
    if _made_by(value, method):
        return [value]  # type: ignore[list-item]
    values = assigned_values(value, package, tree, index)
    if not values or any(i is not index or not (is_none(v) or _made_by(v, method))
                         for v, i in values):
        return None
    return [v for v, _ in values if not is_none(v)] or None  # type: ignore[misc]


def _service_calls(future: ast.expr, package: Package, tree: ast.Module, index: Index,
                   depth: int = 0) -> list[ast.Call] | None:
    """The ``call_async()`` calls ``future`` certainly comes from, or None."""
    registered = done_callback_futures(tree, index).get(id(future))
    if registered is None:
        return _calls(future, "call_async", package, tree, index)
    found: list[ast.Call] = []
    for source in registered:
        calls = _service_calls(source, package, tree, index, depth + 1) \
            if depth < _DEPTH else None
        if calls is None:
            return None
        found.extend(calls)
    return found


def _response(call: ast.Call, package: Package, tree: ast.Module, index: Index,
              known: Known) -> Message | None:
    """The response message class ``<future>.result()`` certainly gives, or None."""
    func = call.func
    if not (isinstance(func, ast.Attribute) and func.attr == "result") or call.args or \
            call.keywords:
        return None
    found: dict[str, Message] = {}
    for service_call in _service_calls(func.value, package, tree, index) or ():
        client = service_call.func.value  # type: ignore[attr-defined]
        for made in _calls(client, "create_client", package, tree, index) or [None]:
            kind = argument(made, PARAMETERS["create_client"], "srv_type") if made else None
            message = known(companion(kind, "Response")) if kind is not None else None
            if message is None:
                return None
            found[message.name] = message
    return next(iter(found.values())) if len(found) == 1 else None


def _result_instances(package: Package, tree: ast.Module, index: Index, known: Known
                      ) -> list[Instance[Message]]:
    """A response used right where ``future.result()`` gives it (``future.result().sum``, or
    ``future.result()`` passed on)."""
    found: list[Instance[Message]] = []
    for call in index.calls:
        if not _made_by(call, "result"):
            continue
        message = _response(call, package, tree, index, known)
        if message is not None:
            parent = index.parents.get(id(call))
            used = isinstance(parent, ast.Attribute) and parent.value is call
            found.append(Instance(message, [parent] if used else [], frozenset(), [call]))
    return found


def message_instances(package: Package, tree: ast.Module, index: Index, known: Known
                      ) -> list[Instance[Message]]:
    """The local variables and ``self.x`` attributes that hold a fresh known message or a
    service's response (``self.x`` also one a callback's message is stored in), the callback
    parameters that get one, and the responses used where ``future.result()`` gives them
    (``known`` must be ``known_messages`` of the tree's package: the result is kept with the
    tree)."""
    return kept(tree, "messages", lambda: _instances(package, tree, index, known))


def _instances(package: Package, tree: ast.Module, index: Index, known: Known
               ) -> list[Instance[Message]]:
    def make(call: ast.Call) -> Message | None:
        return known(call.func) or _response(call, package, tree, index, known)
    received = list(callback_instances(tree, index, known))
    held = {id(ref): instance.message for instance in received for ref in instance.refs
            if isinstance(ref, ast.Name)}
    annotated = [instance for instance in annotated_instances(tree, index, known)
                 if not any(id(ref) in held for ref in instance.refs)]  # not a callback's
    held.update((id(ref), instance.message) for instance in annotated for ref in instance.refs
                if isinstance(ref, ast.Name))
    received.extend(annotated)
    return [*local_instances(tree, index, make), *attribute_instances(tree, index, make, held),
            *received, *_result_instances(package, tree, index, known)]
