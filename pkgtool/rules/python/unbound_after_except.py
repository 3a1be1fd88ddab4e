"""PYC074: code after a ``try`` uses a name only the ``try`` body assigns, and an ``except``
of that ``try`` lets the function go on when the assignment fails."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._try_bindings import (fails_before, harmless, in_loop, inspecting,
                                                none_before, tested_names, uses)
from pkgtool.rules.registry import rule
from pkgtool.rules.scopes import bound_names, scope_bindings
from pkgtool.rules.syntax_trees import Index, installed_trees

_SIMPLE = (ast.Expr, ast.Assign, ast.AugAssign, ast.AnnAssign, ast.Pass)
"""Statements that go on to the next one."""
_STOPPING = ("exit", "abort", "fail", "skip")
"""Words in the name of a call that may end the process or the test (``sys.exit``,
``os.abort``, ``pytest.fail``, ``self.skipTest``): a handler calling one may not go on."""


def _goes_on(handler: ast.ExceptHandler, index: Index) -> bool:
    """True when the handler certainly ends by going on after the ``try``: only simple
    statements (a log line, an assignment), none calling something that stops."""
    return all(isinstance(s, _SIMPLE) for s in handler.body) and not any(
        isinstance(n, ast.Call) and _stops(n, index, 2)
        for s in handler.body for n in ast.walk(s))


def _stops(call: ast.Call, index: Index, depth: int) -> bool:
    """True for a call that may end the process or the test: named so (``sys.exit``,
    ``pytest.fail``), ``parser.error()`` of argparse, or a function of the module whose body
    ends in a ``raise`` or such a call, also in both branches of an ``if``
    (``PrintUsage()``)."""
    func = call.func
    name = func.id if isinstance(func, ast.Name) else \
        func.attr if isinstance(func, ast.Attribute) else ""
    if any(word in name.lower() for word in _STOPPING):
        return True
    if name == "error" and isinstance(func, ast.Attribute) and \
            "parser" in ast.unparse(func.value).lower():
        return True
    if not isinstance(func, ast.Name) or depth == 0:
        return False
    return any(_ends_stopping(f.body, index, depth - 1) for f in index.functions
               if f.name == name)


def _ends_stopping(block: list[ast.stmt], index: Index, depth: int) -> bool:
    """True when ``block`` ends in a ``raise``, a call that stops, or an ``if`` both of whose
    branches do."""
    last = block[-1] if block else None
    if isinstance(last, ast.If):
        return _ends_stopping(last.body, index, depth) and \
            _ends_stopping(last.orelse, index, depth)
    return isinstance(last, ast.Raise) or isinstance(last, ast.Expr) and \
        isinstance(last.value, ast.Call) and _stops(last.value, index, depth)


def _following(node: ast.stmt, index: Index) -> list[ast.stmt]:
    """The statements after ``node`` in its block."""
    parent = index.parents.get(id(node))
    for field in ("body", "orelse", "finalbody"):
        block = getattr(parent, field, None)
        if isinstance(block, list) and any(s is node for s in block):
            return block[[id(s) for s in block].index(id(node)) + 1:]
    return []


def _fails_only_until(body: list[ast.stmt], name: str) -> bool:
    """True when nothing after the statement binding ``name`` can raise: whatever a handler
    catches was raised before ``name`` was bound."""
    at = next(i for i, s in enumerate(body) if name in bound_names([s]))
    return all(harmless(s) for s in body[at + 1:])


def _flag_after(name: str, node: ast.Try) -> set[str]:
    """Names the ``try`` body binds once, in a later statement than ``name``'s binding, with a
    falsy constant (``ok = False``, ``image = None``) before the ``try``: while one is
    truthy, ``name`` is bound."""
    at = next(i for i, s in enumerate(node.body) if name in bound_names([s]))
    later = bound_names(node.body[at + 1:])
    return {flag for flag, count in later.items() if count == 1 and
            bound_names(node.body)[flag] == 1}


def _guarded(use: ast.Name, name: str, node: ast.Try, going_on: list[ast.ExceptHandler],
             rest: list[ast.stmt], index: Index) -> bool:
    """True when ``use`` runs only while a flag of :func:`_flag_after` is truthy (under ``if
    ok:``/``if ok is not None:``, or after ``if not ok: return``), or only after a test of a
    name the handlers that go on set (``status = FAILED`` there, then ``if status ==
    SUCCEEDED:`` around the use, or ``if status != SUCCEEDED: return`` before it)."""
    flags = {f for f in _flag_after(name, node) if _falsy_before(f, node, index)}
    states = _states(going_on, rest)
    child, parent = use, index.parents.get(id(use))
    while parent is not None and parent is not node:
        if isinstance(parent, ast.If) and (
                any(child is s for s in parent.body) and flags & set(tested_names(parent.test))
                or states & _read_names(parent.test)):
            return True
        child, parent = parent, index.parents.get(id(parent))
    for statement in rest:
        if any(n is use for n in ast.walk(statement)):
            return False
        if isinstance(statement, ast.If) and statement.body and \
                isinstance(statement.body[-1], (ast.Return, ast.Raise)) and (
                    _negated_flag(statement.test) in flags or
                    states & _read_names(statement.test)):
            return True
    return False


def _read_names(test: ast.expr) -> set[str]:
    """The names and attribute paths (``self.ready``) ``test`` reads."""
    return {found for n in ast.walk(test) if (found := _path(n)) is not None}


def _path(node: ast.AST) -> str | None:
    """``ok`` for a name, ``self.ok`` for an attribute of a name, else None."""
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name):
        return f"{node.value.id}.{node.attr}"
    return None


def _states(going_on: list[ast.ExceptHandler], rest: list[ast.stmt]) -> set[str]:
    """What the handlers that go on set: the names they bind, and the attributes they set to
    a constant (``self.have_torch = False``; not a counter, ``self.errors += 1``); and the
    names and attributes the statements after the ``try`` then assign from one of those
    (``self.use_gpu = self.device == 'cuda' and self.have_torch``): a test of one tells the
    handler's way from the ``try`` body's."""
    statements = [statement for handler in going_on for statement in handler.body]
    states = set(bound_names(statements)) | {
        found for statement in statements if isinstance(statement, ast.Assign) and
        isinstance(statement.value, ast.Constant) for target in statement.targets
        if isinstance(target, ast.Attribute) and (found := _path(target)) is not None}
    for statement in rest:
        if isinstance(statement, ast.Assign) and states & _read_names(statement.value):
            states.update(found for target in statement.targets
                          if (found := _path(target)) is not None)
    return states


def _negated_flag(test: ast.expr) -> str | None:
    """``ok`` for ``not ok`` and ``ok is None``."""
    if isinstance(test, ast.UnaryOp) and isinstance(test.op, ast.Not) and \
            isinstance(test.operand, ast.Name):
        return test.operand.id
    if isinstance(test, ast.Compare) and isinstance(test.left, ast.Name) and \
            len(test.ops) == 1 and isinstance(test.ops[0], ast.Is) and \
            isinstance(test.comparators[0], ast.Constant) and test.comparators[0].value is None:
        return test.left.id
    return None


def _falsy_before(flag: str, node: ast.Try, index: Index) -> bool:
    """True when ``flag = None`` or ``flag = False`` comes before ``node`` in its block."""
    if none_before(flag, node, index):
        return True
    parent = index.parents.get(id(node))
    block = next((b for b in (getattr(parent, f, None) for f in ("body", "orelse"))
                  if isinstance(b, list) and any(s is node for s in b)), [])
    return any(isinstance(s, ast.Assign) and len(s.targets) == 1 and
               isinstance(s.targets[0], ast.Name) and s.targets[0].id == flag and
               isinstance(s.value, ast.Constant) and s.value.value is False
               for s in block[:[id(b) for b in block].index(id(node))])


def _unbound_reads(index: Index, node: ast.Try) -> Iterator[tuple[ast.Name, str, int, int]]:
    """(read, name, line of its binding, line of the handler that goes on)."""
    going_on = [h for h in node.handlers if _goes_on(h, index)]
    function = index.enclosing_function(node)
    if not going_on or function is None or in_loop(index, node, function) or \
            id(function) in inspecting(index):
        return
    rest = _following(node, index)
    if not rest:
        return
    everywhere = scope_bindings(function)
    for name, count in bound_names(node.body).items():
        if count != everywhere.get(name) or not fails_before(node.body, name) or \
                any(name in bound_names(h.body) for h in node.handlers) or \
                not _fails_only_until(node.body, name):
            continue
        use = next((u for u in uses(rest, name)
                    if not _guarded(u, name, node, going_on, rest, index)), None)
        if use is not None:
            line = next(s.lineno for s in node.body if name in bound_names([s]))
            yield use, name, line, going_on[0].lineno


@rule("PYC074", "unbound-after-except", Severity.ERROR,
      fix="Leave the function in the `except` block (`return`), or give the name a value "
          "there or before `try`")
def unbound_after_except(package: Package) -> Iterator[Hit]:
    """Code after a `try` uses a name only the `try` assigns, and its `except` goes on.

    ## What it does
    In functions of installed modules, reports a read, after a `try` statement, of a local
    name whose only assignments are in the `try` body, after (or in) a statement that can
    raise, when an `except` block of that `try` certainly goes on to the code after it (it
    holds only simple statements, a log line or an assignment of another name, and calls
    nothing that may end the process or the test: `sys.exit`, `os.abort`, `pytest.fail`,
    argparse's `parser.error`, a function of the module ending in one or in `raise`), and
    what it catches can only come before the assignment: nothing after the assignment in
    the `try` can raise.
    Not reported: `try` blocks inside loops, functions calling `locals()`, reads guarded
    by a flag set after the name in the `try` and falsy before it (`ok = False` ... `ok =
    True` ... `if ok:` or `if not ok: return`) or by a test of what the `except` block
    sets (`status = FAILED` there, `if status == SUCCEEDED:` around the read; also an
    attribute, `self.have_torch = False`, and what is assigned from one after the `try`,
    `self.use_gpu = gpu and self.have_torch` ... `if self.use_gpu:`), names the
    `except` block assigns too, and reads that `finally` or a catch-all `except` makes
    (PYC003's).

    ## Why is this bad?
    When the assignment fails, the `except` block logs the error and the function goes on
    to use the name, which then raises `UnboundLocalError`: in a callback, every message
    that fails to convert (`cv_bridge`'s `CvBridgeError`) turns into a crash traceback far
    from its cause, and in `main` the real error is hidden behind the second one.

    ## Example
    ```python
    def on_image(self, msg):
        try:
            frame = self.bridge.imgmsg_to_cv2(msg, 'bgr8')
        except CvBridgeError as error:
            self.get_logger().error(str(error))
        self.detect(frame)
    ```

    ## Use instead
    ```python
    def on_image(self, msg):
        try:
            frame = self.bridge.imgmsg_to_cv2(msg, 'bgr8')
        except CvBridgeError as error:
            self.get_logger().error(str(error))
            return
        self.detect(frame)
    ```
    """
    for module, _, index in installed_trees(package):
        for node in index.tries:
            for use, name, line, handler in _unbound_reads(index, node):
                yield Hit(Span(module.path, use.lineno, use.col_offset + 1),
                          f"`{name}` may be unbound here: only the `try` block assigns it "
                          f"(line {line}), and when that fails the `except` block (line "
                          f"{handler}) goes on to this line: UnboundLocalError",
                          f"Leave the function in the `except` block (`return`), or assign "
                          f"`{name}` there")
