"""Data expressions of setup.py (literals, operators, containers, comprehensions, f-strings)."""

from __future__ import annotations

import ast
import operator
from typing import Any

from pkgtool.model.setup_eval import builtins
from pkgtool.model.setup_eval.bounds import (
    MAX_COST, MAX_SIZE, MAX_STEPS, Budget, TooLarge, binary_size, bounded_percent, length,
    spec_size,
)
from pkgtool.model.setup_eval.scope import Scope
from pkgtool.model.setup_eval.tree import Tree
from pkgtool.model.setup_eval.values import (
    NotStatic, OutOfBudget, PathValue, origins_of, tagged_dict, tagged_list, tagged_str,
    tagged_tuple,
)
from pkgtool.model.span import Span, Unresolved

_COMPARE = {ast.Eq: operator.eq, ast.NotEq: operator.ne, ast.Lt: operator.lt,
            ast.LtE: operator.le, ast.Gt: operator.gt, ast.GtE: operator.ge,
            ast.In: lambda a, b: a in b, ast.NotIn: lambda a, b: a not in b,
            ast.Is: operator.is_, ast.IsNot: operator.is_not}
_ARITHMETIC = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul,
               ast.Mod: operator.mod, ast.FloorDiv: operator.floordiv, ast.Div: operator.truediv}
_SCALARS = (str, int, float, bool, type(None))


class ExpressionEvaluator:
    """Evaluates the data expressions of one setup.py against the package's file tree."""

    def __init__(self, path: str, text: str, files: tuple[str, ...]) -> None:
        self.path = path
        self.lines = text.splitlines()
        self.budget = Budget()
        self.tree = Tree(files, self.budget)
        self.steps = 0
        self.uncertain = 0

    def span(self, node: ast.AST) -> Span:
        """Where ``node`` starts (1-based line and column)."""
        return Span(self.path, getattr(node, "lineno", 1), getattr(node, "col_offset", 0) + 1)

    def unresolved(self, node: ast.AST) -> Unresolved:
        """``node``'s source (its first line, at most 80 characters) and span."""
        line_number, start = getattr(node, "lineno", 1), getattr(node, "col_offset", 0)
        line = self.lines[line_number - 1].encode() if line_number <= len(self.lines) else b""
        same_line = getattr(node, "end_lineno", line_number) == line_number
        end = getattr(node, "end_col_offset", None) if same_line else None
        source = " ".join(line[start:end].decode(errors="replace").split())
        if not same_line or len(source) > 80:
            source = source[:77] + "..."
        return Unresolved(source, self.span(node))

    def refuse(self, node: ast.AST) -> NotStatic:
        """The exception that marks ``node`` as not statically evaluable."""
        return NotStatic(self.unresolved(node))

    def tick(self, node: ast.AST) -> None:
        """Count one step; past the steps or the cost budget every evaluation is refused."""
        self.steps += 1
        if self.steps > MAX_STEPS or self.budget.cost > MAX_COST:
            raise OutOfBudget(self.unresolved(node))

    def eval(self, node: ast.AST, scope: Scope) -> Any:
        """The value of expression ``node``; raises NotStatic when it cannot be known."""
        self.tick(node)
        handler = getattr(self, "_eval_" + type(node).__name__, None)
        if handler is None:
            raise self.refuse(node)
        value = handler(node, scope)
        kind = type(value)
        if kind in (str, list, tuple) and len(value) > MAX_SIZE:
            raise OutOfBudget(self.unresolved(node))
        if kind is str:
            return tagged_str(value, self.span(node))
        if kind is list:
            return tagged_list(value, self.span(node))
        if kind is tuple:
            return tagged_tuple(value, self.span(node))
        if kind is dict:
            return tagged_dict(value, self.span(node))
        return value

    def iterate(self, value: Any, node: ast.AST) -> list[Any]:
        """The items of an iterable value (dict keys, string characters)."""
        if isinstance(value, (list, tuple, str, dict, set, frozenset, range)):
            self.guard(lambda: self.budget.size(len(value)), node)
            return list(value)
        raise self.refuse(node)

    def store(self, target: ast.AST, value: Any, scope: Scope) -> None:
        """Assign ``value`` to a name, an unpacking, or an item of a list or dict."""
        if isinstance(target, ast.Name):
            scope.bind(target.id, value)
        elif isinstance(target, (ast.Tuple, ast.List)):
            items = self.iterate(value, target)
            if len(items) != len(target.elts) or any(isinstance(e, ast.Starred)
                                                     for e in target.elts):
                raise self.refuse(target)
            for element, item in zip(target.elts, items):
                self.store(element, item, scope)
        elif isinstance(target, ast.Subscript):
            container = self.eval(target.value, scope)
            key = self.eval(target.slice, scope)
            if not isinstance(container, (list, dict)):
                raise self.refuse(target)
            self.guard(lambda: container.__setitem__(key, value), target)
        else:
            raise self.refuse(target)

    def guard(self, compute: Any, node: ast.AST) -> Any:
        """Run a pure operation on evaluated data; a Python error in it is refused, and so is
        one past the bounds of :mod:`~pkgtool.model.setup_eval.bounds`."""
        try:
            return compute()
        except TooLarge:
            raise OutOfBudget(self.unresolved(node)) from None
        except (TypeError, ValueError, KeyError, IndexError, AttributeError, ZeroDivisionError,
                OverflowError):
            raise self.refuse(node) from None

    def binary(self, op: ast.operator, left: Any, right: Any, node: ast.AST) -> Any:
        """``left op right`` for strings, sequences, numbers and paths."""
        if isinstance(op, ast.Div) and (isinstance(left, PathValue) or
                                        isinstance(right, PathValue)):
            return builtins.join_paths(self, left, right, node)
        function = _ARITHMETIC.get(type(op))
        if function is None or not _operand_ok(left) or not _operand_ok(right):
            raise self.refuse(node)
        if isinstance(op, ast.Mod) and isinstance(left, str):
            values = builtins.formattable(self, right, node)
            return self.guard(lambda: bounded_percent(self.budget, left, values), node)
        self.guard(lambda: self.budget.size(binary_size(type(op).__name__, left, right)), node)
        result = self.guard(lambda: function(left, right), node)
        if isinstance(result, list):
            return tagged_list(result, self.span(node), origins_of(left, right))
        if isinstance(result, tuple):
            return tagged_tuple(result, self.span(node), origins_of(left, right))
        return result

    # Expressions -------------------------------------------------------------------------

    def _eval_Constant(self, node: ast.Constant, scope: Scope) -> Any:
        return node.value

    def _eval_JoinedStr(self, node: ast.JoinedStr, scope: Scope) -> str:
        pieces: list[str] = []
        for part in node.values:
            if isinstance(part, ast.FormattedValue):
                pieces.append(self._formatted(part, scope))
            else:
                pieces.append(str(self.eval(part, scope)))
            self.guard(lambda: self.budget.size(sum(map(len, pieces))), node)
        return "".join(pieces)

    def _formatted(self, part: ast.FormattedValue, scope: Scope) -> str:
        value = self.eval(part.value, scope)
        value = str(value) if isinstance(value, PathValue) else value
        if not isinstance(value, _SCALARS):
            raise self.refuse(part)
        convert = {115: str, 114: repr, 97: ascii}.get(part.conversion)
        value = convert(value) if convert else value
        spec = str(self.eval(part.format_spec, scope)) if part.format_spec else ""
        self.guard(lambda: self.budget.size(spec_size(value, spec)), part)
        return str(self.guard(lambda: format(value, spec), part))

    def _eval_Subscript(self, node: ast.Subscript, scope: Scope) -> Any:
        container = self.eval(node.value, scope)
        key = self.eval(node.slice, scope)
        if not isinstance(container, (str, list, tuple, dict)):
            raise self.refuse(node)
        return self.guard(lambda: container[key], node)

    def _eval_Slice(self, node: ast.Slice, scope: Scope) -> slice:
        parts = [self.eval(p, scope) if p else None for p in (node.lower, node.upper, node.step)]
        if not all(p is None or type(p) is int for p in parts):
            raise self.refuse(node)
        return slice(*parts)

    def _eval_BinOp(self, node: ast.BinOp, scope: Scope) -> Any:
        return self.binary(node.op, self.eval(node.left, scope), self.eval(node.right, scope),
                           node)

    def _eval_UnaryOp(self, node: ast.UnaryOp, scope: Scope) -> Any:
        value = self.eval(node.operand, scope)
        if isinstance(node.op, ast.Not):
            return not value
        if isinstance(node.op, (ast.USub, ast.UAdd)) and type(value) in (int, float):
            return -value if isinstance(node.op, ast.USub) else value
        raise self.refuse(node)

    def _eval_BoolOp(self, node: ast.BoolOp, scope: Scope) -> Any:
        value = None
        for operand in node.values:
            value = self.eval(operand, scope)
            if bool(value) != isinstance(node.op, ast.And):
                return value
        return value

    def _eval_Compare(self, node: ast.Compare, scope: Scope) -> bool:
        left = self.eval(node.left, scope)
        for op, comparator in zip(node.ops, node.comparators):
            right = self.eval(comparator, scope)
            if not (_operand_ok(left) and _operand_ok(right)):
                raise self.refuse(node)
            self.guard(lambda: self.budget.charge(length(right)), node)
            if not self.guard(lambda: _COMPARE[type(op)](left, right), node):
                return False
            left = right
        return True

    def _eval_IfExp(self, node: ast.IfExp, scope: Scope) -> Any:
        return self.eval(node.body if self.eval(node.test, scope) else node.orelse, scope)

    def _eval_NamedExpr(self, node: ast.NamedExpr, scope: Scope) -> Any:
        value = self.eval(node.value, scope)
        self.store(node.target, value, scope)
        return value

    def _elements(self, nodes: list[ast.expr], scope: Scope) -> tuple[list[Any], tuple[Any, ...]]:
        items: list[Any] = []
        sources: list[Any] = []
        for element in nodes:
            if isinstance(element, ast.Starred):
                value = self.eval(element.value, scope)
                items.extend(self.iterate(value, element))
                sources.append(value)
            else:
                items.append(self.eval(element, scope))
        return items, origins_of(*sources)

    def _eval_List(self, node: ast.List, scope: Scope) -> list[Any]:
        items, origins = self._elements(node.elts, scope)
        return tagged_list(items, self.span(node), origins)

    def _eval_Tuple(self, node: ast.Tuple, scope: Scope) -> tuple[Any, ...]:
        items, origins = self._elements(node.elts, scope)
        return tagged_tuple(items, self.span(node), origins)

    def _eval_Set(self, node: ast.Set, scope: Scope) -> set[Any]:
        items = self._elements(node.elts, scope)[0]
        return set(self.guard(lambda: set(items), node))

    def _eval_Dict(self, node: ast.Dict, scope: Scope) -> dict[Any, Any]:
        result: dict[Any, Any] = {}
        for key, value in zip(node.keys, node.values):
            evaluated = self.eval(value, scope)
            if key is None:
                if not isinstance(evaluated, dict):
                    raise self.refuse(value)
                result.update(evaluated)
            else:
                name = self.eval(key, scope)
                self.guard(lambda: result.__setitem__(name, evaluated), key)
        return result

    def _comprehension(self, node: Any, scope: Scope, produce: Any) -> tuple[Any, ...]:
        local = Scope(scope)
        origins: list[Any] = []

        def loop(index: int) -> None:
            if index == len(node.generators):
                produce(local)
                return
            generator = node.generators[index]
            if generator.is_async:
                raise self.refuse(node)
            iterable = self.eval(generator.iter, local if index else scope)
            items = self.iterate(iterable, generator.iter)
            if not items:
                origins.extend(origins_of(iterable))
            for item in items:
                self.store(generator.target, item, local)
                if all(self.eval(condition, local) for condition in generator.ifs):
                    loop(index + 1)

        loop(0)
        return tuple(origins)

    def _eval_ListComp(self, node: ast.ListComp | ast.GeneratorExp, scope: Scope) -> list[Any]:
        items: list[Any] = []
        origins = self._comprehension(node, scope, lambda s: items.append(self.eval(node.elt, s)))
        return tagged_list(items, self.span(node), origins)

    _eval_GeneratorExp = _eval_ListComp

    def _eval_SetComp(self, node: ast.SetComp, scope: Scope) -> set[Any]:
        items = self._eval_ListComp(node, scope)  # type: ignore[arg-type]
        return set(self.guard(lambda: set(items), node))

    def _eval_DictComp(self, node: ast.DictComp, scope: Scope) -> dict[Any, Any]:
        result: dict[Any, Any] = {}

        def produce(local: Scope) -> None:
            key, value = self.eval(node.key, local), self.eval(node.value, local)
            self.guard(lambda: result.__setitem__(key, value), node)

        self._comprehension(node, scope, produce)
        return result


def _operand_ok(value: Any) -> bool:
    return isinstance(value, (*_SCALARS, list, tuple, dict, set, frozenset, range))
