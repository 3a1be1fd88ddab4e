"""setup.py's names, attribute access and calls, and the setup() call it is run for."""

from __future__ import annotations

import ast
from typing import Any

from pkgtool.model.setup_eval import builtins
from pkgtool.model.setup_eval.expressions import ExpressionEvaluator
from pkgtool.model.setup_eval.commands import Commands, command_classes
from pkgtool.model.setup_eval.scope import Scope
from pkgtool.model.setup_eval.values import Builtin, NotStatic, Opaque
from pkgtool.model.span import Span, Unresolved


class SetupCall:
    """A ``setup(...)`` call reached while running setup.py, filled with its evaluated keywords
    as the evaluator meets them: their ``values``, ``spans`` and ``sources``, and those it
    could not evaluate (``unresolved``); for a list display that could not be evaluated
    whole, the items that could (``in_part``, by keyword)."""

    __slots__ = ("span", "values", "spans", "sources", "unresolved", "in_part", "commands")

    def __init__(self, span: Span) -> None:
        self.span = span
        self.values: dict[str, Any] = {}
        self.spans: dict[str, Span] = {}
        self.sources: dict[str, Unresolved] = {}
        self.unresolved: list[tuple[str, Unresolved]] = []
        self.in_part: dict[str, list[Any]] = {}
        self.commands: Commands | None = None


class Interpreter(ExpressionEvaluator):
    """Evaluates setup.py's expressions, including calls, and records its setup() calls."""

    def __init__(self, path: str, text: str, files: tuple[str, ...]) -> None:
        super().__init__(path, text, files)
        self.setup_calls: list[SetupCall] = []

    def _eval_Name(self, node: ast.Name, scope: Scope) -> Any:
        try:
            value = scope.lookup(node.id)
        except KeyError:
            raise self.refuse(node) from None
        if isinstance(value, Opaque):
            raise NotStatic(value.unresolved)
        return value

    def _eval_Attribute(self, node: ast.Attribute, scope: Scope) -> Any:
        return builtins.attribute(self, self.eval(node.value, scope), node.attr, node)

    def _eval_Call(self, node: ast.Call, scope: Scope) -> Any:
        try:
            function = self.eval(node.func, scope)
        except NotStatic as error:
            if _called_name(node) == "setup":
                return self.record_setup(node, scope, exact=False)
            if _inside(error.unresolved.span, node):
                raise self.refuse(node) from None
            raise
        if isinstance(function, Builtin) and function.name in builtins.SETUP_FUNCTIONS:
            return self.record_setup(node, scope, exact=True)
        args: list[Any] = []
        kwargs: dict[str, Any] = {}
        for argument in node.args:
            if isinstance(argument, ast.Starred):
                args.extend(self.iterate(self.eval(argument.value, scope), argument))
            else:
                args.append(self.eval(argument, scope))
        for keyword in node.keywords:
            value = self.eval(keyword.value, scope)
            if keyword.arg is not None:
                kwargs[keyword.arg] = value
            elif isinstance(value, dict) and all(isinstance(k, str) for k in value):
                kwargs.update(value)
            else:
                raise self.refuse(keyword.value)
        return self.call(function, args, kwargs, node)

    def call(self, function: Any, args: list[Any], kwargs: dict[str, Any], node: ast.Call
             ) -> Any:
        """Call an allow-listed function, a method of evaluated data, or a setup.py function."""
        return builtins.call(self, function, args, kwargs, node)

    def record_setup(self, node: ast.Call, scope: Scope, *, exact: bool) -> None:
        """Evaluate each keyword of a setup() call on its own and remember the call."""
        call = SetupCall(self.span(node))
        if not exact or self.uncertain:
            call.unresolved.append(("**", self.unresolved(node.func if not exact else node)))
        for keyword in node.keywords:
            key = keyword.arg or "**"
            if key == "cmdclass":
                call.commands = command_classes(keyword.value)
            try:
                value = self.eval(keyword.value, scope)
            except NotStatic as error:
                call.unresolved.append((key, error.unresolved))
                if isinstance(keyword.value, (ast.List, ast.Tuple)):
                    call.in_part[key] = self._evaluable_items(keyword.value, scope)
                continue
            except RecursionError:
                call.unresolved.append((key, self.unresolved(keyword.value)))
                continue
            if keyword.arg is not None:
                call.values[key] = value
                call.spans[key] = self.span(keyword.value)
                call.sources[key] = self.unresolved(keyword.value)
            elif isinstance(value, dict) and all(isinstance(k, str) for k in value):
                for name, item in value.items():
                    call.values[name] = item
                    call.spans[name] = self.span(keyword.value)
                    call.sources[name] = self.unresolved(keyword.value)
            else:
                call.unresolved.append((key, self.unresolved(keyword.value)))
        self.setup_calls.append(call)

    def _evaluable_items(self, display: ast.List | ast.Tuple, scope: Scope) -> list[Any]:
        """The values of the items of ``display`` that evaluate (``*rest`` left out)."""
        found = []
        for item in display.elts:
            if not isinstance(item, ast.Starred):
                try:
                    found.append(self.eval(item, scope))
                except (NotStatic, RecursionError):
                    continue
        return found


def _called_name(node: ast.Call) -> str | None:
    func = node.func
    return func.id if isinstance(func, ast.Name) else getattr(func, "attr", None)


def _inside(span: Span, node: ast.AST) -> bool:
    """True when ``span`` lies within ``node``'s source lines."""
    first = getattr(node, "lineno", 0)
    return first <= span.line <= (getattr(node, "end_lineno", None) or first)
