"""What the rules on a node's ``__init__`` and its callbacks share: the methods ``__init__``
calls and registers as timer, subscription and service callbacks, and the methods assigning
each attribute of ``self`` (PYC090, PYC092)."""

from __future__ import annotations

import ast

from pkgtool.model.ast_nodes import subtree
from pkgtool.rules.call_graph import reached
from pkgtool.rules.syntax_trees import FUNCTIONS, Index

CALLBACK_AT = {"create_timer": 1, "create_subscription": 2, "create_service": 2}
"""Node methods registering a callback, by where their ``callback`` argument stands."""
Method = ast.FunctionDef | ast.AsyncFunctionDef
Methods = dict[str, Method]


def methods_of(cls: ast.ClassDef) -> Methods:
    """The methods of ``cls`` by name."""
    return {f.name: f for f in cls.body if isinstance(f, FUNCTIONS)}


def called_methods(init: Method, methods: Methods) -> list[Method]:
    """The methods of the class ``__init__`` calls on ``self``, and those they call."""
    def callee(call: ast.Call, caller: Method) -> Method | None:
        func = call.func
        return methods[func.attr] if isinstance(func, ast.Attribute) and \
            is_self(func.value, caller) and func.attr in methods and \
            func.attr != "__init__" else None
    return reached([init], callee)


def registered_callbacks(init: Method, methods: Methods) -> dict[str, set[str]]:
    """The methods ``__init__`` registers with ``self.create_timer``,
    ``self.create_subscription`` and ``self.create_service``, by registering method."""
    found: dict[str, set[str]] = {method: set() for method in CALLBACK_AT}
    for node in subtree(init):
        if not (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and
                node.func.attr in CALLBACK_AT and is_self(node.func.value, init)):
            continue
        if any(k.arg == "autostart" for k in node.keywords) or _cancelled(node, init):
            continue  # a timer started later, maybe once a message came
        at = CALLBACK_AT[node.func.attr]
        given = node.args[at] if len(node.args) > at else next(
            (k.value for k in node.keywords if k.arg == "callback"), None)
        if isinstance(given, ast.Attribute) and is_self(given.value, init) and \
                given.attr in methods:
            found[node.func.attr].add(given.attr)
    return found


def _cancelled(call: ast.Call, init: Method) -> bool:
    """True when ``__init__`` assigns the timer ``call`` makes to ``self.x`` and calls
    ``self.x.cancel()`` (a callback resets it later)."""
    stored = {t.attr for n in subtree(init) if isinstance(n, (ast.Assign, ast.AnnAssign)) and
              n.value is call for t in (n.targets if isinstance(n, ast.Assign) else [n.target])
              if isinstance(t, ast.Attribute) and is_self(t.value, init)}
    return any(isinstance(n, ast.Attribute) and n.attr == "cancel" and
               isinstance(n.value, ast.Attribute) and n.value.attr in stored and
               is_self(n.value.value, init) for n in subtree(init))


def attribute_setters(cls: ast.ClassDef, index: Index, methods: Methods, *,
                      calls_unknown: bool = True) -> dict[str, set[str]]:
    """Each attribute of ``self`` assigned in the class, with the methods assigning it; an
    attribute also assigned elsewhere (a nested function, another receiver) or by a method
    the class calls itself (``self.on_scan(first)``; unless not ``calls_unknown``) maps to
    no method (an empty set)."""
    called = {n.func.attr for n in subtree(cls) if isinstance(n, ast.Call) and
              isinstance(n.func, ast.Attribute) and isinstance(n.func.value, ast.Name) and
              n.func.value.id == "self"} if calls_unknown else set()
    found: dict[str, set[str]] = {}
    unknown: set[str] = set()
    for node in subtree(cls):
        if not isinstance(node, ast.Attribute) or isinstance(node.ctx, ast.Load):
            continue
        function = index.enclosing_function(node)
        name = function.name if function is not None else None
        if name in methods and methods[name] is function and name not in called and \
                is_self(node.value, function):
            found.setdefault(node.attr, set()).add(name)
        else:
            unknown.add(node.attr)
    return {attr: set() if attr in unknown else where for attr, where in found.items()}


def is_self(value: ast.expr, function: Method) -> bool:
    """True when ``value`` is the name of the method's first parameter (``self``)."""
    arguments = function.args.posonlyargs + function.args.args
    return isinstance(value, ast.Name) and bool(arguments) and value.id == arguments[0].arg
