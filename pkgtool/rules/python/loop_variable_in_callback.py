"""PYC094: a callback made inside a loop reads a name the loop rebinds."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._callbacks import callback_arguments
from pkgtool.rules.registry import rule
from pkgtool.rules.scopes import NESTED_SCOPES, scope_walk
from pkgtool.rules.syntax_trees import FUNCTIONS, Index

_LASTING = frozenset({"create_subscription()", "create_service()", "create_timer()",
                      "ActionServer()"})
"""The registrations whose callback runs for as long as the node does (not a future's)."""
_COMPREHENSIONS = (ast.ListComp, ast.SetComp, ast.DictComp, ast.GeneratorExp)
_LOOPS = (ast.For, ast.AsyncFor)
Closure = ast.Lambda | ast.FunctionDef | ast.AsyncFunctionDef


@rule("PYC094", "loop-variable-in-callback", Severity.ERROR,
      fix="Bind the value when the callback is made: `lambda msg, robot=robot: ...`, or "
          "`functools.partial(self.on_msg, robot=robot)`")
def loop_variable_in_callback(package: Package) -> Iterator[Hit]:
    """A subscription, service, timer or action server callback made inside a loop (a
    `lambda`, or a function defined in the loop) reads a name the loop rebinds on each turn.

    ## What it does
    For the callback given to `create_subscription`, `create_service`, `create_timer` or
    `ActionServer` inside a `for` loop or a comprehension, finds the names the callback reads
    without binding them itself (as a parameter, or a default) that the loop binds: its
    target, or a name assigned in its body. Loops that may end early (`break`, `return`)
    or that spin the node on each turn (a call named `spin...`) are left alone.

    ## Why is this bad?
    Python looks a closure's free names up when the function runs, not when it is made.
    rclpy runs the callbacks once the loop has ended, so every one of them sees the value of
    the last turn: all robots' messages are counted as the last robot's, without a word.

    ## Example
    ```python
    for robot in robots:
        self.create_subscription(
            BatteryState, f'{robot}/battery', lambda msg: self.on_battery(robot, msg), 10)
    ```

    ## Use instead
    ```python
    for robot in robots:
        self.create_subscription(
            BatteryState, f'{robot}/battery',
            lambda msg, robot=robot: self.on_battery(robot, msg), 10)
    ```
    """
    for path, value, api, _, index, _ in callback_arguments(package):
        if api not in _LASTING:
            continue
        for loop, rebound in _loops_around(value, index):
            closure = value if isinstance(value, ast.Lambda) else _defined_in(loop, value)
            read = sorted(_free_reads(closure) & rebound) if closure is not None else []
            if read:
                names = ", ".join(f"`{n}`" for n in read)
                yield Hit(Span(path, value.lineno, value.col_offset + 1),
                          f"The callback given to {api} reads {names}, which the enclosing "
                          f"loop rebinds: it is looked up when the callback runs, after the "
                          f"loop, so every callback sees the last turn's value",
                          f"Bind the values when the callback is made: give it the parameters "
                          f"{', '.join(f'`{n}={n}`' for n in read)}, or pass "
                          f"`functools.partial(callback, {', '.join(read)})`")
                break


def _loops_around(node: ast.AST, index: Index) -> Iterator[tuple[ast.AST, set[str]]]:
    """The ``for`` loops and comprehensions around ``node`` within its function (innermost
    first) that run it on each turn, with the names each rebinds; loops that may end early
    or spin the node are left out."""
    child, parent = node, index.parents.get(id(node))
    while parent is not None and not isinstance(
            parent, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda, ast.ClassDef)):
        if isinstance(parent, _LOOPS) and any(child is s for s in parent.body) and \
                not _may_end_early(parent):
            targets = _names_bound(parent.target)
            yield parent, targets | _assigned(parent.body, targets)
        elif isinstance(parent, _COMPREHENSIONS) and child is not parent.generators[0].iter:
            yield parent, set().union(*(_names_bound(g.target) for g in parent.generators))
        child, parent = parent, index.parents.get(id(parent))


def _may_end_early(loop: ast.For | ast.AsyncFor) -> bool:
    """True when the loop's own body breaks or returns, or calls something named ``spin...``
    (the callbacks may run before the next turn) or ``destroy...`` (``destroy_subscription``:
    the registration ends within the turn)."""
    for node in scope_walk(loop.body):
        if isinstance(node, (ast.Break, ast.Return)) and not _in_inner_loop(node, loop):
            return True
        if isinstance(node, ast.Call) and _called_name(node).startswith(("spin", "destroy")):
            return True  # callbacks run in the turn, or the registration ends with it
    return False


def _in_inner_loop(node: ast.AST, loop: ast.AST) -> bool:
    """True when a ``break`` or ``return`` belongs to a loop nested in ``loop`` (a ``return``
    never does: it ends every loop)."""
    if isinstance(node, ast.Return):
        return False
    inner = [n for n in scope_walk(loop.body) if isinstance(n, (*_LOOPS, ast.While))]
    return any(node is n for inner_loop in inner for n in scope_walk(inner_loop.body))


def _called_name(call: ast.Call) -> str:
    func = call.func
    return func.id if isinstance(func, ast.Name) else \
        func.attr if isinstance(func, ast.Attribute) else ""


def _names_bound(target: ast.AST) -> set[str]:
    """The names an assignment target binds (not ``self`` of ``self.x``)."""
    return {n.id for n in ast.walk(target) if isinstance(n, ast.Name) and
            isinstance(n.ctx, ast.Store)}


def _assigned(body: list[ast.stmt], varying: set[str]) -> set[str]:
    """The names a loop body binds in its own scope to values that read a name that
    changes from turn to turn (``varying``, the loop's target, or such a name), and the
    functions it defines: ``logger = self.get_logger()`` is the same object every turn."""
    found: set[str] = set()
    assignments = [n for n in scope_walk(body) if isinstance(n, (ast.Assign, ast.AnnAssign,
                                                                 ast.AugAssign, ast.For))]
    found.update(n.name for n in scope_walk(body) if isinstance(n, FUNCTIONS))
    grew = True
    while grew:
        known = varying | found
        grew = False
        for node in assignments:
            value = node.iter if isinstance(node, ast.For) else node.value
            targets = [node.target] if not isinstance(node, ast.Assign) else node.targets
            reads = {n.id for n in ast.walk(value) if isinstance(n, ast.Name)} \
                if value is not None else set()
            names = set().union(*(_names_bound(t) for t in targets)) - found
            if names and (reads & known or isinstance(node, (ast.AugAssign, ast.For))):
                found |= names
                grew = True
    return found


def _defined_in(loop: ast.AST, value: ast.expr) -> Closure | None:
    """The function a ``for`` loop's body defines under the name ``value`` reads, if any."""
    if not isinstance(value, ast.Name) or not isinstance(loop, _LOOPS):
        return None
    return next((n for n in scope_walk(loop.body) if isinstance(
        n, (ast.FunctionDef, ast.AsyncFunctionDef)) and n.name == value.id), None)


def _free_reads(closure: Closure) -> set[str]:
    """The names a function reads that nothing inside it binds (parameters, defaults'
    targets, assignments, nested functions' own names)."""
    body = [closure.body] if isinstance(closure, ast.Lambda) else closure.body
    inside = [n for part in body for n in ast.walk(part)]
    bound = {a.arg for n in [closure, *inside] if isinstance(n, (ast.Lambda, *NESTED_SCOPES))
             for a in _arguments(n)}
    bound |= {n.id for n in inside if isinstance(n, ast.Name) and not isinstance(n.ctx, ast.Load)}
    bound |= {n.name for n in inside if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef,
                                                       ast.ClassDef))}
    return {n.id for n in inside if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Load)
            } - bound


def _arguments(function: ast.AST) -> list[ast.arg]:
    arguments = getattr(function, "args", None)
    if not isinstance(arguments, ast.arguments):
        return []
    return [a for a in (*arguments.posonlyargs, *arguments.args, *arguments.kwonlyargs,
                        arguments.vararg, arguments.kwarg) if a is not None]
