"""PYC024: a callback whose parameters cannot take the arguments rclpy passes it."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.rules.python._callbacks import Argument, callback_arguments
from pkgtool.rules.syntax_trees import Index, installed_trees, overridden
from pkgtool.rules.python._message_instances import callback_function
from pkgtool.rules.registry import rule

_PASSED = {
    ("create_timer()", "callback"): ((0,), "no argument"),
    ("create_subscription()", "callback"): (
        (1, 2), "the message (and optionally its MessageInfo)"),
    ("create_service()", "callback"): ((2,), "the request and a response to fill in"),
    ("ActionServer()", "execute_callback"): ((1,), "the goal handle"),
    ("ActionServer()", "goal_callback"): ((1,), "the goal request"),
    ("ActionServer()", "cancel_callback"): ((1,), "the goal handle"),
    ("ActionServer()", "handle_accepted_callback"): ((1,), "the goal handle"),
    ("add_done_callback()", "callback"): ((1,), "the future"),
}
"""(API, callback parameter) -> the numbers of positional arguments rclpy (Jazzy) calls the
callback with, and what they are."""


def _accepts(arguments: ast.arguments, skip: int, count: int) -> bool:
    """True when a function with ``arguments`` (after ``skip`` bound ones) can be called with
    ``count`` positional arguments."""
    positional = [*arguments.posonlyargs, *arguments.args][skip:]
    required = len(positional) - len(arguments.defaults)
    keyword_only = any(d is None for d in arguments.kw_defaults)
    return not keyword_only and required <= count and (
        count <= len(positional) or arguments.vararg is not None)


def _timer_info(arguments: ast.arguments, index: Index) -> bool:
    """True when a parameter is annotated ``TimerInfo`` (newer rclpy fills one so annotated
    with the timer's call times; another annotation changes nothing): the name as written, or
    imported under another (``TimerInfo as Info``); a string annotation too, on the safe side."""
    every = (*arguments.posonlyargs, *arguments.args, *arguments.kwonlyargs)
    return any(a.annotation is not None and (
        "TimerInfo" in ast.unparse(a.annotation) or
        (index.qualified(a.annotation) or "").endswith(".TimerInfo")) for a in every)


@rule("PYC024", "callback-signature-mismatch", Severity.ERROR,
      fix="Give the callback the parameters rclpy passes: `def on_message(self, msg)`, "
          "`def on_timer(self)`, `def on_request(self, request, response)`")
def callback_signature_mismatch(package: Package) -> Iterator[Hit]:
    """A callback cannot be called with the arguments rclpy passes it.

    ## What it does
    Checks the callbacks given to `create_timer` (called with no argument),
    `create_subscription` (the message, or the message and its `MessageInfo`),
    `create_service` (the request and the response), `ActionServer`'s `execute_callback`,
    `goal_callback`, `cancel_callback` and `handle_accepted_callback` (one argument) and
    `add_done_callback` (the future), and the `registerCallback` of a message_filters
    `TimeSynchronizer` or `ApproximateTimeSynchronizer` made from a list of `n` filters (`n`
    messages, then the extra arguments given to `registerCallback`), when the callback is a
    lambda, a plain method of the
    registering class (`self.on_message`) or a plain function bound once in the module:
    reports one whose required parameters are more than rclpy passes, whose positional
    parameters are fewer, or that has a keyword-only parameter without default. Functions
    with a parameter annotated `TimerInfo` (newer rclpy fills it) and decorated functions
    are left alone.

    ## Why is this bad?
    rclpy calls the callback with a fixed number of arguments: the call raises `TypeError`
    in the executor the first time the timer fires or a message or request arrives, and the
    node dies (a subscription callback that takes neither one nor two arguments fails at
    once on Jazzy with `RuntimeError`). Forgetting the message parameter, or `response` of
    a service, is the usual cause.

    ## Example
    ```python
    self.create_subscription(String, 'chatter', self.on_message, 10)

    def on_message(self):
        self.get_logger().info('got one')
    ```

    ## Use instead
    ```python
    self.create_subscription(String, 'chatter', self.on_message, 10)

    def on_message(self, msg):
        self.get_logger().info('got one')
    ```
    """
    for path, value, api, parameter, index, tree in (*callback_arguments(package),
                                                     *_synchronized(package)):
        passed = _PASSED.get((api, parameter)) or _synchronizer_passes(api)
        if isinstance(value, ast.Lambda):
            found: tuple[ast.Lambda | ast.FunctionDef | ast.AsyncFunctionDef, int] | None = (
                value, 0)
        else:
            found = callback_function(value, tree, index)
        if passed is None or found is None or _timer_info(found[0].args, index) or \
                overridden(package, found[0], index):
            continue  # (last: a subclass's method may be the one that runs)
        counts, what = passed
        if not any(_accepts(found[0].args, found[1], count) for count in counts):
            name = "the lambda" if isinstance(value, ast.Lambda) else f"`{ast.unparse(value)}`"
            yield Hit(Span(path, value.lineno, value.col_offset + 1),
                      f"`{api.split()[0][:-2]}` calls {name} with {what}, which its "
                      "parameters cannot take: the call raises TypeError")


_SYNCHRONIZERS = frozenset({"message_filters.TimeSynchronizer",
                            "message_filters.ApproximateTimeSynchronizer"})
_SYNCHRONIZED = "registerCallback()"


def _synchronized(package: Package) -> Iterator[Argument]:
    """The callbacks given to ``registerCallback`` of a message_filters synchronizer made from
    a list of ``n`` filters (bound once in the module, to a name or ``self.x``), the API
    written ``registerCallback() <n>`` (with the extra arguments it passes on added)."""
    for module, tree, index in installed_trees(package):
        if not index.imports_from("message_filters"):
            continue  # no synchronizer made here
        made: dict[str, list[int | None]] = {}
        for node in nodes_of_class(tree, ast.Assign):
            value = node.value  # type: ignore[attr-defined]
            inputs = value.args[0] if isinstance(value, ast.Call) and value.args and \
                index.qualified(value.func) in _SYNCHRONIZERS else None
            count = len(inputs.elts) if isinstance(inputs, (ast.List, ast.Tuple)) and not any(
                isinstance(e, ast.Starred) for e in inputs.elts) else None
            for target in node.targets:  # type: ignore[attr-defined]
                made.setdefault(ast.unparse(target), []).append(count)
        for call in index.calls:
            func = call.func
            if not isinstance(func, ast.Attribute) or func.attr != "registerCallback" or \
                    not call.args or any(isinstance(a, ast.Starred) for a in call.args):
                continue
            counts = made.get(ast.unparse(func.value), [])
            if len(counts) == 1 and counts[0] is not None:
                passed = counts[0] + len(call.args) - 1
                yield module.path, call.args[0], f"{_SYNCHRONIZED} {passed}", "callback", \
                    index, tree


def _synchronizer_passes(api: str) -> tuple[tuple[int, ...], str] | None:
    """What a synchronizer's ``registerCallback`` passes (:func:`_synchronized`'s API)."""
    if not api.startswith(_SYNCHRONIZED):
        return None
    count = int(api.rsplit(" ", 1)[1])
    return (count,), f"{count} argument{'s' if count != 1 else ''} (one message per input)"
