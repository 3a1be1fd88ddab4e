"""PYC026: a service, action (execute, goal, cancel) or set-parameters callback that never
returns its result."""

from __future__ import annotations

import ast
from collections.abc import Iterator
from typing import NamedTuple

from pkgtool.findings import Hit, Severity, shortened
from pkgtool.model.ast_nodes import last_name
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._assignments import made_class
from pkgtool.rules.python._callbacks import callback_arguments
from pkgtool.rules.python._field_reads import field_reads
from pkgtool.rules.python._message_instances import Function, binding_counts, callback_function
from pkgtool.rules.python._value_types import PARAMETER, PARAMETER_TEXT, certain_type
from pkgtool.rules.registry import rule
from pkgtool.rules.scopes import plainly_decorated, returns_none, scope_walk
from pkgtool.rules.syntax_trees import FUNCTIONS, Index, installed_trees, overridden
from pkgtool.lazy_regex import lazy_pattern


class _Callback(NamedTuple):
    """A callback whose value rclpy uses, and what to say of it."""

    what: str
    returned: str
    never: str
    """What rclpy does when the callback never returns its result."""
    here: str
    """What rclpy does when the callback returns something else (or falls off its end)."""
    fix: str
    instead: str
    """How to fix a return of something else."""
    rejects: bool = False
    """rclpy takes anything but the accepting value as a rejection: a ``return False`` or
    ``return None`` beside others rejects, as its author meant."""


_RETURNED = {
    ("create_service()", "callback"): _Callback(
        "service callback", "the response",
        "rclpy's send_response() raises TypeError on the first request",
        "rclpy's send_response() raises TypeError", "End the callback with `return response`",
        "Return the response rclpy passes in, its fields set: `return response`"),
    ("ActionServer()", "execute_callback"): _Callback(
        "action execute callback", "the result", "the client never gets the goal's result",
        "the client never gets the goal's result",
        "End the callback with `return result`, the action's `Result()`",
        "Return the action's `Result()`, its fields set"),
    ("ActionServer()", "goal_callback"): _Callback(
        "action goal callback", "a `GoalResponse`", "rclpy rejects every goal",
        "rclpy rejects the goal (it accepts only `GoalResponse.ACCEPT`)",
        "End the callback with `return GoalResponse.ACCEPT` (or `REJECT`)",
        "Return `GoalResponse.ACCEPT` or `GoalResponse.REJECT`", rejects=True),
    ("ActionServer()", "cancel_callback"): _Callback(
        "action cancel callback", "a `CancelResponse`", "rclpy rejects every cancel request",
        "rclpy rejects the cancel request (it accepts only `CancelResponse.ACCEPT`)",
        "End the callback with `return CancelResponse.ACCEPT` (or `REJECT`)",
        "Return `CancelResponse.ACCEPT` or `CancelResponse.REJECT`", rejects=True),
    ("add_on_set_parameters_callback()", "callback"): _Callback(
        "set-parameters callback", "a `SetParametersResult`",
        "every parameter change fails: rclpy reads `.successful` of the `None` it gets "
        "(AttributeError)",
        "rclpy reads `.successful` of a `SetParametersResult` from it to accept the change",
        "End the callback with `return SetParametersResult(successful=True)`",
        "Return `SetParametersResult(successful=...)`"),
}
"""The callbacks whose value rclpy uses, by API and parameter."""
_RESULT_ARGUMENT = {"create_service()": 1}
"""The position of the argument a callback may return as its result (a service's response),
by API; the callback's other arguments never are."""
_STOPS = (ast.Return, ast.Raise, ast.Try, ast.With, ast.AsyncWith, ast.Match)
"""Statements after which the end of a body may not be reached (or not only by falling)."""


def _never_passed(statement: ast.stmt) -> bool:
    """True for a ``while`` loop the code after it may not follow (or only at shutdown): one
    whose test holds until shutdown (``while True:``, ``while rclpy.ok():``) or whose ``else``
    block returns or raises, with no ``break`` of its own."""
    if not isinstance(statement, ast.While) or _breaks(statement.body):
        return False
    test = statement.test
    return isinstance(test, ast.Constant) and bool(test.value) or \
        isinstance(test, ast.Call) and last_name(test.func) == "ok" or \
        bool(statement.orelse) and _leaves(statement.orelse)


def _breaks(body: list[ast.stmt]) -> bool:
    """True when ``body`` (of a loop) holds a ``break`` of that loop (not of a loop in it)."""
    stack: list[ast.AST] = list(body)
    while stack:
        node = stack.pop()
        if isinstance(node, ast.Break):
            return True
        if not isinstance(node, (ast.For, ast.AsyncFor, ast.While, *FUNCTIONS, ast.ClassDef)):
            stack.extend(ast.iter_child_nodes(node))
        else:
            stack.extend(getattr(node, "orelse", []))  # a loop's else: still this loop's
    return False


_PLAIN_ENDS = (ast.Expr, ast.Assign, ast.AugAssign, ast.AnnAssign)


_RESULT_KINDS = lazy_pattern(r"_(Response|Result)$")
"""Field types a callback's result could be (a message holding a service response or action
result: the field may be returned)."""
_MESSAGE_CLASS = lazy_pattern(r"\w+\.msg\.\w+")
"""The qualified name of a message class (not a service's or action's message)."""
_NOT_RESULTS = frozenset({"int", "float", "complex", "str", "bytes", "bool", "NoneType",
                          "list", "tuple", "dict", "set", PARAMETER, PARAMETER_TEXT})
"""Certain types (:func:`~._value_types.certain_type`) a callback's result never has."""


def _wrong_returns(function: Function, arguments: list[str], result: str | None,
                   messages: bool, package: Package, tree: ast.Module, index: Index
                   ) -> Iterator[tuple[ast.AST, str]]:
    """The ``return`` statements of ``function`` (not of functions inside it) whose value is
    certainly not the callback's result, each with what it returns instead: an imported
    interface class itself, ``None`` (beside returns of a value), a value of a builtin type
    (``return True``), one of the callback's ``arguments`` (never rebound) other than
    ``result`` (the request, the goal handle, the parameter list), a field of one of them or
    of another message (``response.sum``), or with ``messages`` an instance of a message
    (``nav_msgs.msg.Path``: never a service's response or an action's result)."""
    if any(isinstance(n, (ast.Yield, ast.YieldFrom)) for n in scope_walk(function.body)):
        return
    bound, reads = binding_counts(function), field_reads(tree, index, package)
    given = {name for name in arguments if bound[name] == 1}
    replaced = _replaced_by_finally(function)
    for node in scope_walk(function.body):
        if not isinstance(node, ast.Return) or id(node) in replaced:
            continue
        value, root = node.value, node.value
        while isinstance(root, ast.Attribute):
            root = root.value
        read = reads.get(id(value))
        if value is None or isinstance(value, ast.Constant) and value.value is None:
            yield node, "nothing (`None`)"
        elif isinstance(value, (ast.Name, ast.Attribute)) and \
                certain_type(value, package, tree, index) == "type":
            yield value, f"the class `{ast.unparse(value)}`"
        elif isinstance(value, ast.Name) and value.id in given and value.id != result:
            yield value, f"its argument `{value.id}`"
        elif isinstance(value, ast.Attribute) and (
                read is not None and not _RESULT_KINDS.search(read.kind) or
                read is None and isinstance(root, ast.Name) and root.id in given):
            owner = "an attribute of its argument" if read is None else "a field of"
            yield value, f"`{_shown(value)}`, {owner} `{_shown(root)}`"
        elif messages and (made := made_class(value, package, tree, index, _MESSAGE_CLASS)):
            yield value, f"`{_shown(value)}`, a `{made}` message"
        elif (found := certain_type(value, package, tree, index, texts=True)) in _NOT_RESULTS:
            kind = found.split(" ")[0]
            yield value, f"`{_shown(value)}`, {'an' if kind[0] in 'aeiou' else 'a'} {kind}"


def _replaced_by_finally(function: Function) -> set[int]:
    """Ids of the ``return`` statements of ``function`` inside a ``try`` (its body, handlers
    or ``else``) whose ``finally`` certainly ends in a ``return`` or ``raise``: that one
    replaces what they return."""
    replaced: set[int] = set()
    for node in scope_walk(function.body):
        if isinstance(node, ast.Try) and node.finalbody and _leaves(node.finalbody):
            replaced.update(id(inner) for part in (node.body, node.orelse, *(
                handler.body for handler in node.handlers))
                for inner in scope_walk(part) if isinstance(inner, ast.Return))
    return replaced


def _leaves(body: list[ast.stmt]) -> bool:
    """True when running ``body`` certainly ends in a ``return`` or ``raise`` (its last
    statement is one, or an ``if`` each of whose branches ends so)."""
    last = body[-1]
    return isinstance(last, (ast.Return, ast.Raise)) or isinstance(last, ast.If) and \
        bool(last.orelse) and _leaves(last.body) and _leaves(last.orelse)


def _rejection(returned: ast.AST) -> bool:
    """True for a bare ``return``, ``return None`` or ``return False``."""
    value = returned.value if isinstance(returned, ast.Return) else returned
    return value is None or isinstance(value, ast.Constant) and value.value in (None, False)


def _shown(value: ast.expr) -> str:
    return shortened(ast.unparse(value))


def _falls_off_the_end(function: ast.FunctionDef | ast.AsyncFunctionDef) -> bool:
    """True for a plain ``def`` (no decorator but ``staticmethod``/``classmethod``, no
    ``yield``) whose body certainly can end without a ``return``: no top-level statement of
    it returns, raises, loops on past its end (:func:`_never_passed`) or enters
    ``try``/``with``/``match``, and the last one is an expression or assignment (not a call
    of an ``exit``)."""
    last = function.body[-1]
    if not isinstance(function, ast.FunctionDef) or not plainly_decorated(function) or \
            any(isinstance(s, _STOPS) or _never_passed(s) for s in function.body) or \
            not isinstance(last, _PLAIN_ENDS) or isinstance(last, ast.Expr) and (
                isinstance(last.value, ast.Constant) or "exit" in ast.unparse(last.value)):
        return False
    return not any(isinstance(n, (ast.Yield, ast.YieldFrom)) for n in scope_walk(function.body))


@rule("PYC026", "service-callback-returns-nothing", Severity.ERROR,
      fix="End the callback with `return response`")
def service_callback_returns_nothing(package: Package) -> Iterator[Hit]:
    """A service, action or set-parameters callback never returns its result.

    ## What it does
    Reports the callback given to `create_service`, the `execute_callback`, `goal_callback`
    and `cancel_callback` of an rclpy `ActionServer`, the callback given to
    `add_on_set_parameters_callback`, and the transition callbacks (`on_configure`,
    `on_activate`, ...) of a class deriving from rclpy's `LifecycleNode`, when it is a
    plain method of the registering class (`self.on_request`) or a plain function bound once
    in the module, and certainly returns `None`: no `return <value>` anywhere, no `yield`,
    not `async`, no decorator, not a placeholder body (only `pass`, `...`, a docstring or
    `raise`). Also reports such a callback that returns a value on some paths but certainly
    can fall off its end: no statement of its body (outside nested blocks) returns, raises,
    loops with no way past it (`while True:` or `while rclpy.ok():` with no `break`, a
    `while` whose `else` block returns) or enters `try`, `with` or `match`, and the last one
    is an expression or assignment (`self.get_logger().info('done')` after an early
    `return`, after a `while` loop that returns the result when the goal is reached and ends
    when its test fails).
    And each `return` of such a callback whose value is certainly not its result: an imported
    interface class itself (`return AddTwoInts.Response`), `None` or a bare `return` (beside
    returns of a value), a number, string, bool, tuple or other builtin value (`return True`
    from a set-parameters callback), one of the callback's arguments (never rebound) other
    than a service's response (`return request`, `return goal_handle`), a field of one of them
    or of another message (`return response.sum`, `return result.sequence`), or, from a
    service or action callback, an instance of a message (`plan = Path()`, `return plan`:
    never a service response or action result). Generators are left alone, and so are a bare
    `return`, `return None` and `return False` in a goal or cancel callback: they reject, as
    meant.

    ## Why is this bad?
    rclpy sends what the callback returns as the response: `None` makes
    `Service.send_response` raise `TypeError` in the executor on the first request, the
    node dies and the client waits forever. Filling in the `response` argument is not
    enough: it must be returned. An action server whose execute callback returns `None`
    never answers the client's result request (checked on Jazzy), and a set-parameters
    callback must return a `SetParametersResult`: with `None` or any other value (`True`),
    rclpy rejects every change (`ros2 param set` fails). A goal or cancel callback must
    return `GoalResponse.ACCEPT` or `CancelResponse.ACCEPT` to accept: rclpy compares what it
    returns with those members of a plain `Enum`, so `True` rejects every goal or cancel
    request (checked on Jazzy). A lifecycle node's transition callback must return a
    `TransitionCallbackReturn`: rclpy calls `.to_label()` on what it returns, so `None` or
    `True` raises `AttributeError` and the transition never completes. Returning the field a
    client reads
    (`response.sum`) instead of the response is the same mistake: `send_response` raises
    `TypeError` for anything but the service's response; an execute callback returning the
    result's sequence instead of the result raises `AttributeError` in the executor (both
    checked on Jazzy).

    ## Example
    ```python
    def on_request(self, request, response):
        response.success = True
    ```

    ## Use instead
    ```python
    def on_request(self, request, response):
        response.success = True
        return response
    ```
    """
    for path, value, api, parameter, index, tree in callback_arguments(package):
        kind = _RETURNED.get((api, parameter))
        found = callback_function(value, tree, index) if kind else None
        if kind is None or found is None or overridden(package, found[0], index):
            continue  # a subclass's method may be the one that runs
        function = found[0]
        parameters = function.args.posonlyargs + function.args.args
        arguments = [a.arg for a in parameters[found[1]:]]
        position = _RESULT_ARGUMENT.get(api)
        result = arguments[position] if position is not None and position < len(arguments) \
            else None
        messages = api != "add_on_set_parameters_callback()"  # SetParametersResult is one
        yield from _callback_hits(path, function, f"`{ast.unparse(value)}`", kind,
                                  (arguments, result, messages),
                                  (Span(path, value.lineno, value.col_offset + 1),),
                                  (package, tree, index))
    for path, function, cls, tree, index in _lifecycle_callbacks(package):
        arguments = [a.arg for a in (function.args.posonlyargs + function.args.args)[1:]]
        yield from _callback_hits(path, function, f"`{cls.name}.{function.name}`", _LIFECYCLE,
                                  (arguments, None, False), (), (package, tree, index))


def _callback_hits(path: str, function: Function, shown: str, kind: _Callback,
                   given: tuple[list[str], str | None, bool], related: tuple[Span, ...],
                   where: tuple[Package, ast.Module, Index]) -> Iterator[Hit]:
    """The hits of one callback ``function`` (``shown`` as written where it is registered):
    it never returns its result, returns something else, or falls off its end. ``given``:
    its arguments, the one that is its result (a service's response) and whether a message
    instance is never its result."""
    what, returned = kind.what, kind.returned
    if returns_none(function):
        yield Hit(Span(path, function.lineno, function.col_offset + 1),
                  f"The {what} {shown} never returns {returned}: {kind.never}", kind.fix,
                  related=related)
        return
    arguments, result, messages = given
    for returned_value, instead in _wrong_returns(function, arguments, result, messages,
                                                  *where):
        if kind.rejects and _rejection(returned_value):
            continue
        yield Hit(Span(path, returned_value.lineno, returned_value.col_offset + 1),
                  f"The {what} {shown} returns {instead}, not {returned}: {kind.here}",
                  kind.instead, related=related)
    if _falls_off_the_end(function):
        end = function.body[-1]
        yield Hit(Span(path, end.lineno, end.col_offset + 1),
                  f"The {what} {shown} returns {returned} on some paths but ends here without "
                  f"a `return`: when it gets here, {kind.here}", kind.fix, related=related)


_LIFECYCLE = _Callback(
    "lifecycle callback", "a `TransitionCallbackReturn`",
    "rclpy's state change calls `.to_label()` on what it returns and raises AttributeError: "
    "the transition never completes",
    "rclpy's state change calls `.to_label()` on it and raises AttributeError",
    "End the callback with `return TransitionCallbackReturn.SUCCESS`",
    "Return `TransitionCallbackReturn.SUCCESS`, `FAILURE` or `ERROR`")
_TRANSITIONS = frozenset({"on_configure", "on_cleanup", "on_shutdown", "on_activate",
                          "on_deactivate", "on_error"})
"""The transition callbacks a lifecycle node's class overrides."""
_LIFECYCLE_NODES = frozenset({"rclpy.lifecycle.Node", "rclpy.lifecycle.LifecycleNode",
                              "rclpy.lifecycle.node.LifecycleNode"})


def _lifecycle_callbacks(package: Package
                         ) -> Iterator[tuple[str, Function, ast.ClassDef, ast.Module, Index]]:
    """The plain transition callbacks (``on_configure``...) of classes deriving from rclpy's
    lifecycle node directly: path, method, class, tree and index."""
    for module, tree, index in installed_trees(package):
        for cls in index.classes:
            if not any(index.qualified(base) in _LIFECYCLE_NODES for base in cls.bases):
                continue
            for method in cls.body:
                if isinstance(method, ast.FunctionDef) and method.name in _TRANSITIONS and \
                        not method.decorator_list:
                    yield module.path, method, cls, tree, index
