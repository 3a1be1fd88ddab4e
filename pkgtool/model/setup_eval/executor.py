"""Statements of setup.py run over evaluated data: assignments, loops, ifs, functions, imports.

A statement the evaluator cannot run makes every name it might change opaque, so later uses
are unresolved instead of wrong.
"""

from __future__ import annotations

import ast
from typing import Any

from pkgtool.model.setup_eval.builtins import CONSTANTS, MODULES, SETUP_FUNCTIONS, is_function
from pkgtool.model.setup_eval.evaluator import Interpreter
from pkgtool.model.setup_eval.scope import Scope
from pkgtool.model.setup_eval.taint import changed_names
from pkgtool.model.setup_eval.values import BoundMethod, Builtin, NotStatic, Opaque, UserFunc
from pkgtool.model.span import Unresolved
from pkgtool.model.static_branches import truth

MAX_CALL_DEPTH = 16
TAINT_COST = 250
"""Budget units per syntax node walked to taint a refused statement (a Python-level walk
costs about what 250 characters of string work do)."""


class _Break(Exception):
    """``break`` leaving a loop."""


class _Continue(Exception):
    """``continue`` in a loop."""


class _Return(Exception):
    """``return`` leaving a function with its (possibly opaque) value."""

    def __init__(self, value: Any) -> None:
        super().__init__()
        self.value = value


CONTROL_FLOW = (_Break, _Continue, _Return)
"""Exceptions of break/continue/return that escape to the module level (ignored there)."""


class Runner(Interpreter):
    """Runs setup.py's statements; ``setup_calls`` collects the setup() calls reached."""

    depth = 0
    uncertain_exits = 0
    """How many ``return``, ``break`` and ``continue`` statements ran under a test not
    evaluated (they may or may not leave their function or loop)."""

    def __init__(self, path: str, text: str, files: tuple[str, ...]) -> None:
        super().__init__(path, text, files)
        self._sizes: dict[int, int] = {}

    def run_block(self, statements: list[ast.stmt], scope: Scope) -> None:
        """Run ``statements`` in order."""
        for statement in statements:
            self.run(statement, scope)

    def run(self, statement: ast.stmt, scope: Scope) -> None:
        """Run one statement; if it cannot be evaluated, what it changes becomes opaque."""
        handler = getattr(self, "_run_" + type(statement).__name__, None)
        try:
            self.tick(statement)
            if handler is None:
                raise self.refuse(statement)
            handler(statement, scope)
        except NotStatic as error:
            self.taint(statement, scope, error.unresolved)
        except RecursionError:
            self.taint(statement, scope, self.unresolved(statement))

    def taint(self, node: ast.AST, scope: Scope, why: Unresolved) -> None:
        """Bind every name ``node`` may assign or mutate to an opaque value.

        Walking ``node`` costs its size: charged, so a refused statement in a long loop
        exhausts the budget instead of being walked again and again.
        """
        size = self._sizes.setdefault(id(node), sum(1 for _ in ast.walk(node)))
        self.budget.cost += TAINT_COST * size
        for name in changed_names(node, scope):
            owner = _owner(scope, name)
            owner.names[name] = Opaque(why)

    def call_user(self, function: UserFunc, args: list[Any], kwargs: dict[str, Any],
                  node: ast.Call) -> Any:
        """Call a function defined in setup.py by running its body in a new scope."""
        definition = function.node
        if not isinstance(definition, ast.FunctionDef) or definition.decorator_list or \
                self.depth >= MAX_CALL_DEPTH:
            raise self.refuse(node)
        local = Scope(function.scope)
        self._bind_arguments(definition.args, args, kwargs, local, function.scope, node)
        self.depth += 1
        exits = self.uncertain_exits
        try:
            self.run_block(definition.body, local)
            returned: Any = None
        except _Return as done:
            returned = done.value
        except (_Break, _Continue):
            raise self.refuse(node) from None
        finally:
            self.depth -= 1
        if self.uncertain_exits != exits:  # it may have returned elsewhere, or something else
            raise self.refuse(node)
        if isinstance(returned, Opaque):
            raise NotStatic(returned.unresolved)
        return returned

    def _bind_arguments(self, spec: ast.arguments, args: list[Any], kwargs: dict[str, Any],
                        local: Scope, defining: Scope, node: ast.Call) -> None:
        positional = [*spec.posonlyargs, *spec.args]
        if len(args) > len(positional) and not spec.vararg:
            raise self.refuse(node)
        defaults = dict(zip([a.arg for a in positional][::-1], spec.defaults[::-1]))
        defaults |= {a.arg: d for a, d in zip(spec.kwonlyargs, spec.kw_defaults) if d}
        remaining = dict(kwargs)
        for index, parameter in enumerate([*positional, *spec.kwonlyargs]):
            if index < len(positional) and index < len(args):
                local.bind(parameter.arg, args[index])
            elif parameter.arg in remaining:
                local.bind(parameter.arg, remaining.pop(parameter.arg))
            elif parameter.arg in defaults:
                local.bind(parameter.arg, self.eval(defaults[parameter.arg], defining))
            else:
                raise self.refuse(node)
        if spec.vararg:
            local.bind(spec.vararg.arg, tuple(args[len(positional):]))
        if spec.kwarg:
            local.bind(spec.kwarg.arg, remaining)
        elif remaining:
            raise self.refuse(node)

    # Statements --------------------------------------------------------------------------

    def _run_Expr(self, node: ast.Expr, scope: Scope) -> None:
        self.eval(node.value, scope)

    def _run_Assign(self, node: ast.Assign, scope: Scope) -> None:
        value = self.eval(node.value, scope)
        for target in node.targets:
            self.store(target, value, scope)

    def _run_AnnAssign(self, node: ast.AnnAssign, scope: Scope) -> None:
        if node.value is not None:
            self.store(node.target, self.eval(node.value, scope), scope)

    def _run_AugAssign(self, node: ast.AugAssign, scope: Scope) -> None:
        target = node.target
        if isinstance(target, ast.Name):
            load: ast.expr = ast.Name(target.id, ast.Load())
        elif isinstance(target, ast.Subscript):
            load = ast.Subscript(target.value, target.slice, ast.Load())
        else:
            raise self.refuse(node)
        current = self.eval(ast.copy_location(load, target), scope)
        value = self.eval(node.value, scope)
        if isinstance(current, list) and isinstance(node.op, ast.Add):
            self.call(BoundMethod(current, "extend"), [value], {}, node)  # type: ignore[arg-type]
        else:
            self.store(target, self.binary(node.op, current, value, node), scope)

    def _run_For(self, node: ast.For, scope: Scope) -> None:
        """Run the loop; when a ``break`` or ``continue`` under a test not evaluated may have
        left it early, what it changes becomes opaque."""
        items = self.iterate(self.eval(node.iter, scope), node.iter)
        exits = self.uncertain_exits
        for item in items:
            self.tick(node)
            self.store(node.target, item, scope)
            try:
                self.run_block(node.body, scope)
            except _Break:
                break
            except _Continue:
                continue
        else:
            self.run_block(node.orelse, scope)
        if self.uncertain_exits != exits:
            raise self.refuse(node)

    def _run_If(self, node: ast.If, scope: Scope) -> None:
        """A test not evaluated runs both branches (uncertain), unless it is one that never
        changes for a ROS 2 build (``if ROS_VERSION == 1:`` before catkin's setup call)."""
        try:
            test = bool(self.eval(node.test, scope))
        except NotStatic as error:
            decided = truth(node.test, {})
            if decided is not None:
                self.run_block(node.body if decided else node.orelse, scope)
                return
            self.uncertain += 1
            try:
                for branch in (node.body, node.orelse):
                    try:
                        self.run_block(branch, scope)
                    except CONTROL_FLOW:  # a return, break or continue that may not happen
                        self.uncertain_exits += 1
            finally:
                self.uncertain -= 1
            for branch in (*node.body, *node.orelse):
                self.taint(branch, scope, error.unresolved)
            return
        self.run_block(node.body if test else node.orelse, scope)

    def _run_Try(self, node: ast.Try, scope: Scope) -> None:
        """Run the body as if nothing raised; what a handler would change becomes opaque.

        Handlers made only of imports (``except ImportError: from distutils.core import
        setup``) are fallbacks to an equivalent module and change nothing.
        """
        self.run_block(node.body, scope)
        self.run_block(node.orelse, scope)
        fallbacks = (ast.Import, ast.ImportFrom, ast.Pass)
        for handler in node.handlers:
            if not all(isinstance(statement, fallbacks) for statement in handler.body):
                self.taint(handler, scope, self.unresolved(handler))
        self.run_block(node.finalbody, scope)

    _run_TryStar = _run_Try

    def _run_With(self, node: ast.With, scope: Scope) -> None:
        for item in node.items:
            self.taint(item, scope, self.unresolved(item.context_expr))
        self.run_block(node.body, scope)

    def _run_FunctionDef(self, node: ast.FunctionDef, scope: Scope) -> None:
        scope.bind(node.name, UserFunc(node, scope))

    def _run_Import(self, node: ast.Import, scope: Scope) -> None:
        for alias in node.names:
            if alias.asname:
                scope.bind(alias.asname, self._module(alias.name, node))
            else:
                top = alias.name.split(".")[0]
                scope.bind(top, self._module(top, node))

    def _run_ImportFrom(self, node: ast.ImportFrom, scope: Scope) -> None:
        for alias in node.names:
            if alias.name == "*":
                raise self.refuse(node)
            qualified = f"{node.module}.{alias.name}"
            known = node.level == 0 and node.module in MODULES
            value: Any = Opaque(self.unresolved(node))
            if known and qualified in CONSTANTS:
                value = CONSTANTS[qualified]
            elif known and (qualified in MODULES or qualified in SETUP_FUNCTIONS or
                            is_function(qualified)):
                value = Builtin(qualified)
            scope.bind(alias.asname or alias.name, value)

    def _module(self, name: str, node: ast.AST) -> Any:
        return Builtin(name) if name in MODULES else Opaque(self.unresolved(node))

    def _run_Global(self, node: ast.Global, scope: Scope) -> None:
        scope.declared_global.update(node.names)

    def _run_Delete(self, node: ast.Delete, scope: Scope) -> None:
        for target in node.targets:
            if not isinstance(target, ast.Name):
                raise self.refuse(node)
            scope.unbind(target.id)

    def _run_Return(self, node: ast.Return, scope: Scope) -> None:
        try:
            value = self.eval(node.value, scope) if node.value else None
        except NotStatic as error:
            value = Opaque(error.unresolved)
        raise _Return(value)

    def _run_Break(self, node: ast.Break, scope: Scope) -> None:
        raise _Break

    def _run_Continue(self, node: ast.Continue, scope: Scope) -> None:
        raise _Continue

    def _run_Pass(self, node: ast.stmt, scope: Scope) -> None:
        return None

    _run_Assert = _run_Raise = _run_Pass


def _owner(scope: Scope, name: str) -> Scope:
    current: Scope | None = scope
    while current is not None:
        if name in current.names:
            return current.module if name in current.declared_global else current
        current = current.parent
    return scope
