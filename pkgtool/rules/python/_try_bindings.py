"""What a ``try`` body binds, and where that binding may be missing: the shared part of
PYC003 (reads in ``finally``/``except``) and PYC074 (reads after an ``except`` that goes on)."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.model.memo import per_tree
from pkgtool.rules.scopes import bound_names, catches_name_error, own_scope, scope_walk
from pkgtool.rules.syntax_trees import Index

_LOOPS = (ast.For, ast.AsyncFor, ast.While)


_LOG_LEVELS = frozenset({"debug", "info", "warn", "warning", "error", "fatal", "critical"})


def _logs(statement: ast.stmt) -> bool:
    """A log line or ``print()`` whose arguments call nothing (``self.get_logger().info(
    f'Connecting to {port}...')``): it does not raise in practice."""
    call = statement.value if isinstance(statement, ast.Expr) else None
    if not isinstance(call, ast.Call):
        return False
    func = call.func
    logger = isinstance(func, ast.Attribute) and func.attr in _LOG_LEVELS and (
        isinstance(func.value, ast.Call) and isinstance(func.value.func, ast.Attribute) and
        func.value.func.attr == "get_logger" or
        isinstance(func.value, ast.Name) and "log" in func.value.id.lower())
    printed = isinstance(func, ast.Name) and func.id == "print"
    return (logger or printed) and not any(
        isinstance(n, ast.Call) for a in (*call.args, *(k.value for k in call.keywords))
        for n in ast.walk(a))


_CLOCKS = frozenset({"time", "monotonic", "perf_counter", "process_time", "time_ns",
                     "monotonic_ns", "perf_counter_ns", "process_time_ns"})
"""``time`` functions that read a clock and never raise."""


def harmless(statement: ast.stmt) -> bool:
    """Statements that cannot raise (in practice): ``pass``, assignments of literals, names or
    a clock's reading (``started = time.perf_counter()``), and log lines (:func:`_logs`)."""
    if isinstance(statement, ast.Pass) or _logs(statement):
        return True
    value = statement.value if isinstance(statement, (ast.Assign, ast.AnnAssign)) else None
    if isinstance(value, ast.Call) and not value.args and not value.keywords and \
            isinstance(value.func, ast.Attribute) and value.func.attr in _CLOCKS and \
            isinstance(value.func.value, ast.Name) and value.func.value.id == "time":
        return True
    return value is not None and all(
        isinstance(n, (ast.Constant, ast.Name, ast.List, ast.Tuple, ast.Dict, ast.Set, ast.Load))
        for n in ast.walk(value))


def fails_before(body: list[ast.stmt], name: str) -> bool:
    """True when a statement of ``body`` that may raise runs before ``name`` is bound."""
    for statement in body:
        if name in bound_names([statement]):
            return not harmless(statement)
        if not harmless(statement):
            return True
    return False


def uses(body: list[ast.stmt], name: str) -> Iterator[ast.Name]:
    """Reads of ``name`` in ``body``, except inside ``try`` blocks that catch NameError, and
    in the ``else`` of one whose body reads the bare name (``try: name / except NameError:
    ... / else: use(name)``: the ``else`` runs only when the name is bound)."""
    tested: set[int] = set()
    for node in scope_walk(body, skip_protected=True):
        if isinstance(node, ast.Try) and any(
                catches_name_error(h) for h in node.handlers) and any(
                isinstance(s, ast.Expr) and isinstance(s.value, ast.Name) and
                s.value.id == name for s in node.body):
            tested.update(id(n) for statement in node.orelse for n in ast.walk(statement))
        elif isinstance(node, ast.Name) and node.id == name and \
                isinstance(node.ctx, ast.Load) and id(node) not in tested:
            yield node


def in_loop(index: Index, node: ast.AST, function: ast.AST) -> bool:
    parent = index.parents.get(id(node))
    while parent is not None and parent is not function:
        if isinstance(parent, _LOOPS):
            return True
        parent = index.parents.get(id(parent))
    return False


@per_tree
def inspecting(index: Index) -> set[int]:
    """Ids of the functions whose body (not a scope inside it) calls ``locals()``, ``vars()``
    or ``globals()``: they may inspect their own namespace."""
    found: set[int] = set()
    for call in index.calls:
        if isinstance(call.func, ast.Name) and call.func.id in ("locals", "vars", "globals"):
            scope, way = own_scope(call, index.parents)
            if isinstance(scope, (ast.FunctionDef, ast.AsyncFunctionDef)) and \
                    any(way is statement for statement in scope.body):
                found.add(id(scope))
    return found


def tested_names(test: ast.expr) -> Iterator[str]:
    """The names (and ``self.x``, as written) a test requires to be truthy or not None
    (``a``, ``a is not None``, and the parts of an ``and``)."""
    if isinstance(test, ast.BoolOp) and isinstance(test.op, ast.And):
        for value in test.values:
            yield from tested_names(value)
        return
    if isinstance(test, ast.Compare) and len(test.ops) == 1 and \
            isinstance(test.ops[0], ast.IsNot) and isinstance(test.comparators[0], ast.Constant) \
            and test.comparators[0].value is None:
        test = test.left
    if isinstance(test, ast.Name):
        yield test.id
    elif isinstance(test, ast.Attribute) and isinstance(test.value, ast.Name):
        yield ast.unparse(test)


def statements_before(node: ast.stmt, index: Index) -> list[ast.stmt]:
    """The statements before ``node`` in its block (empty when it starts the block)."""
    parent = index.parents.get(id(node))
    for block in (getattr(parent, field, None) for field in ("body", "orelse", "finalbody")):
        if isinstance(block, list) and any(s is node for s in block):
            return block[:[id(b) for b in block].index(id(node))]
    return []


def none_before(guard: str, node: ast.Try, index: Index) -> bool:
    """True when a statement before ``node`` in its block is ``guard = None``."""
    return any(isinstance(s, ast.Assign) and len(s.targets) == 1 and
               isinstance(s.targets[0], ast.Name) and s.targets[0].id == guard and
               isinstance(s.value, ast.Constant) and s.value.value is None
               for s in statements_before(node, index))
