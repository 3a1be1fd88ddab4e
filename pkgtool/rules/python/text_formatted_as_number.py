"""PYC040: a value that is (or on some path is) a str, formatted as a number."""

from __future__ import annotations

import ast
import re
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._format_specs import format_specs, percent_values
from pkgtool.rules.python._message_instances import binding_counts
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, installed_trees
from pkgtool.lazy_regex import lazy_pattern

_SPEC = lazy_pattern(r"(?:.(?P<align>[<>=^])|(?P<first>[<>=^]))?(?P<sign>[-+ ])?(?P<z>z)?"
                     r"(?P<alt>#)?0?\d*(?P<group>[,_])?(?:\.\d+)?(?P<type>[bcdeEfFgGnosxX%])?",
                     re.S)
"""Python's format specification mini-language (``[[fill]align][sign][z][#][0][width]
[grouping][.precision][type]``), the parts a str refuses named."""
_PERCENT_ERRORS = {**dict.fromkeys("diu", "%{} format: a real number is required, not str"),
                   **dict.fromkeys("oxX", "%{} format: an integer is required, not str"),
                   **dict.fromkeys("eEfFgG", "must be real number, not str")}
"""``%`` conversions that raise TypeError for a str, with Python's message (``%c`` takes a
one-character str)."""
_TEXT_BUILTINS = frozenset({"str", "repr", "ascii", "format", "chr", "hex", "oct", "bin"})
"""Builtins that always return a str."""
_TEXT_METHODS = frozenset({"format", "join", "upper", "lower", "strip", "lstrip", "rstrip",
                           "replace", "title", "capitalize", "center", "ljust", "rjust"})
"""Methods of a str literal that return a str."""
_CAUGHT = frozenset({"ValueError", "TypeError", "Exception", "BaseException"})
_GUARDS = frozenset({"isinstance", "type", "callable", "hasattr", "float", "int"})
"""Calls whose appearance with the name means the code looks at what the value is."""
_DEPTH = 4


def refused_by_text(spec: str) -> str | None:
    """What Python says formatting a str with the format ``spec`` raises, or None when a str
    takes it (``>8``, ``.3``, ``s``)."""
    match = _SPEC.fullmatch(spec)
    if match is None:
        return None
    kind = match["type"]
    if kind and kind != "s":
        return f"ValueError: Unknown format code '{kind}' for object of type 'str'"
    if match["sign"]:
        return "ValueError: Sign not allowed in string format specifier"
    if match["z"]:
        return "ValueError: Negative zero coercion (z) not allowed in string format specifier"
    if match["alt"]:
        return "ValueError: Alternate form (#) not allowed in string format specifier"
    if match["group"]:
        return f"ValueError: Cannot specify '{match['group']}' with 's'."
    if "=" in (match["align"], match["first"]):
        return "ValueError: '=' alignment not allowed in string format specifier"
    return None


class _Texts:
    """Which expressions of one module may be a str where they are read."""

    def __init__(self, tree: ast.Module, index: Index) -> None:
        self.tree = tree
        self.index = index

    def text(self, value: ast.expr, depth: int = 0) -> ast.expr | None:
        """The expression that makes ``value`` a str on some path (a literal, a conversion),
        or None when nothing shows it may be one."""
        if depth > _DEPTH:
            return None
        if isinstance(value, ast.Constant):
            return value if isinstance(value.value, str) else None
        if isinstance(value, ast.JoinedStr) or self._text_call(value):
            return value
        if isinstance(value, ast.IfExp):
            return self.text(value.body, depth + 1) or self.text(value.orelse, depth + 1)
        if isinstance(value, ast.BoolOp):
            return next(filter(None, (self.text(v, depth + 1) for v in value.values)), None)
        if isinstance(value, ast.Name) and isinstance(value.ctx, ast.Load):
            return self._name_text(value, depth)
        return None

    def _text_call(self, value: ast.expr) -> bool:
        if not isinstance(value, ast.Call):
            return False
        func = value.func
        if isinstance(func, ast.Name):
            return func.id in _TEXT_BUILTINS and func.id not in self.index.bound
        return isinstance(func, ast.Attribute) and func.attr in _TEXT_METHODS and \
            isinstance(func.value, ast.Constant) and isinstance(func.value.value, str)

    def _name_text(self, name: ast.Name, depth: int) -> ast.expr | None:
        """A str one of the assignments reaching this read of a function's local gives."""
        function = self.index.enclosing_function(name, through_lambdas=False)
        if function is None or self._guarded(name, function):
            return None
        stores = self._stores(name.id, function)
        if stores is None:
            return None
        if not stores and not any(self._binds(a, name.id) for a in ast.walk(function.args)):
            return self._constant_text(name.id, depth)
        chain = self._chain(name, function)
        for statement in self._reaching(stores, name, chain):
            found = self.text(statement.value, depth + 1)  # type: ignore[arg-type]
            if found is not None:
                return found
        return None

    def _constant_text(self, name: str, depth: int) -> ast.expr | None:
        """The str a module-level constant gives: the module binds ``name`` once, with a
        plain assignment at its top level."""
        if binding_counts(self.tree)[name] != 1:
            return None
        store = next((s for s in self.tree.body if isinstance(s, ast.Assign) and any(
            isinstance(t, ast.Name) and t.id == name for t in s.targets)), None)
        return self.text(store.value, depth + 1) if store is not None else None

    def _stores(self, name: str, function: ast.AST) -> list[ast.stmt] | None:
        """The plain assignments (``name = ...``) of ``name`` in ``function``; None when it is
        also bound another way there (a loop, ``+=``, unpacking, ``global``, a nested
        scope)."""
        stores: list[ast.stmt] = []
        for node in ast.walk(function):
            if isinstance(node, (ast.Global, ast.Nonlocal)) and name in node.names:
                return None
            if isinstance(node, ast.Name) and node.id == name and \
                    not isinstance(node.ctx, ast.Load):
                parent = self.index.parents.get(id(node))
                if isinstance(parent, ast.Assign) and any(t is node for t in parent.targets) \
                        or isinstance(parent, ast.AnnAssign) and parent.value is not None \
                        and parent.target is node:
                    if self.index.enclosing_function(node, through_lambdas=False) \
                            is not function:
                        return None
                    stores.append(parent)
                else:
                    return None
            elif isinstance(node, (ast.arg, ast.FunctionDef, ast.AsyncFunctionDef,
                                   ast.ClassDef, ast.ExceptHandler, ast.Import,
                                   ast.ImportFrom)) and node is not function and \
                    self._binds(node, name):
                return None
        return stores

    @staticmethod
    def _binds(node: ast.AST, name: str) -> bool:
        if isinstance(node, ast.arg):
            return node.arg == name
        if isinstance(node, (ast.Import, ast.ImportFrom)):
            return any((a.asname or a.name.split(".")[0]) == name for a in node.names)
        return getattr(node, "name", None) == name

    def _chain(self, node: ast.AST, function: ast.AST) -> list[ast.AST]:
        """The nodes from ``node`` up to ``function``."""
        chain = [node]
        while chain[-1] is not function:
            parent = self.index.parents.get(id(chain[-1]))
            if parent is None:
                break
            chain.append(parent)
        return chain

    def _reaching(self, stores: list[ast.stmt], use: ast.Name, chain: list[ast.AST]
                  ) -> list[ast.stmt]:
        """The assignments before ``use`` that no later statement on every path to it
        replaces: an assignment in a block around the read, before it, or a statement there
        that assigns the name on each of its ways through (``if``/``else`` both assigning)."""
        inside = {id(n) for n in chain}
        read_at = (use.lineno, use.col_offset)
        before = [s for s in stores if id(s) not in inside and
                  (s.end_lineno or s.lineno, s.end_col_offset or 0) <= read_at]
        mine = {id(s) for s in stores}
        replacing: list[ast.stmt] = []
        for child, parent in zip(chain, chain[1:]):
            for field in ("body", "orelse", "finalbody", "handlers"):
                block = getattr(parent, field, None)
                if isinstance(block, list) and any(s is child for s in block):
                    position = next(i for i, s in enumerate(block) if s is child)
                    replacing += [s for s in block[:position] if _assigns(s, mine)]
        last = max(replacing, key=lambda s: (s.lineno, s.col_offset), default=None)
        return [s for s in before if last is None or s is last or
                (s.lineno, s.col_offset) > (last.lineno, last.col_offset)]

    def _guarded(self, name: ast.Name, function: ast.AST) -> bool:
        """True when the function tests the name (compares it, asks its type, branches on
        it) or the read sits in a ``try`` that catches the error."""
        for node in ast.walk(function):
            if isinstance(node, ast.Compare) and _mentions(node, name.id):
                return True
            if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and \
                    node.func.id in _GUARDS and _mentions(node, name.id):
                return True
            test = getattr(node, "test", None) if isinstance(
                node, (ast.If, ast.While, ast.IfExp, ast.Assert)) else None
            if test is not None and _mentions(test, name.id):
                return True
            if isinstance(node, ast.Match) and _mentions(node.subject, name.id):
                return True
        return any(isinstance(n, ast.Try) and any(_catches(h) for h in n.handlers)
                   for n in self._chain(name, function))


def _assigns(statement: ast.stmt, stores: set[int]) -> bool:
    """True when ``statement`` assigns the name on every way through it that goes on: it is
    one of the name's ``stores``, or an ``if`` (or ``try``) each branch of which does, or
    leaves (``return``, ``raise``, ``continue``, ``break``)."""
    if id(statement) in stores:
        return True
    if isinstance(statement, ast.If):
        return _block_assigns(statement.body, stores) and \
            _block_assigns(statement.orelse, stores)
    if isinstance(statement, ast.Try):
        return _block_assigns(statement.body + statement.orelse, stores) and all(
            _block_assigns(h.body, stores) for h in statement.handlers)
    if isinstance(statement, (ast.With, ast.AsyncWith)):
        return _block_assigns(statement.body, stores)
    return False


def _block_assigns(block: list[ast.stmt], stores: set[int]) -> bool:
    return any(_assigns(s, stores) or isinstance(s, (ast.Return, ast.Raise, ast.Continue,
                                                     ast.Break)) for s in block)


def _mentions(node: ast.AST, name: str) -> bool:
    return any(isinstance(n, ast.Name) and n.id == name for n in ast.walk(node))


def _catches(handler: ast.ExceptHandler) -> bool:
    kinds = handler.type
    if kinds is None:
        return True
    names = kinds.elts if isinstance(kinds, ast.Tuple) else [kinds]
    return any(isinstance(n, ast.Name) and n.id in _CAUGHT for n in names)


def _percent_values(node: ast.BinOp) -> Iterator[tuple[ast.expr, str, str]]:
    """(value, conversion, the error) of each number conversion of ``'...' % values``."""
    for value, match in percent_values(node):
        if match["type"] in _PERCENT_ERRORS:
            error = _PERCENT_ERRORS[match["type"]].format(match["type"])
            yield value, match.group(0), f"TypeError: {error}"


def _formatted(tree: ast.Module, index: Index) -> Iterator[tuple[ast.expr, str, str, bool]]:
    """(value, specification, the error, converted) of every place a value is formatted
    with a specification a str refuses; ``converted``: ``!r``/``!s``/``!a`` made it a str."""
    for value, spec, converted in format_specs(tree, index):
        refused = refused_by_text(spec)
        if refused:
            yield value, spec, refused, converted
    for node in nodes_of_class(tree, ast.BinOp):
        if isinstance(node.op, ast.Mod) and isinstance(node.left, ast.Constant) and \
                isinstance(node.left.value, str):  # type: ignore[attr-defined]
            for value, conversion, refused in _percent_values(node):  # type: ignore[arg-type]
                yield value, conversion, refused, False


def _what(value: ast.expr, source: ast.expr) -> str:
    shown = ast.unparse(value)
    if source is value:
        return f"`{shown}` is a str"
    given = ast.unparse(source)
    return f"`{shown}` may be the str `{given if len(given) <= 40 else given[:37] + '...'}` " \
        f"(line {source.lineno})"


@rule("PYC040", "text-formatted-as-number", Severity.ERROR,
      fix="Format the text apart from the number (`f'{value}'` when it is text), or give a "
          "number where the text is (`float('nan')`)")
def text_formatted_as_number(package: Package) -> Iterator[Hit]:
    """A str, or a value that is a str on some path, is formatted as a number.

    ## What it does
    Reports a value formatted with a number's format (`f'{v:.2f}'`, `'{:d}'.format(v)`,
    `format(v, '.1%')`, `'%.3f' % v`) when the value is a str: a literal, an f-string, a
    conversion (`str(x)`), a field converted with `!r`/`!s`, or a local name an assignment
    reaching that line gives one, also on one branch only (`x if ok else 'N/A'`, `x or ''`).
    A name the function compares, checks the type of or branches on, and a line inside a
    `try` that catches the error, are left alone.

    ## Why is this bad?
    A str refuses number formats: `f"{'N/A':.4f}"` raises `ValueError: Unknown format code
    'f' for object of type 'str'` and `'%.2f' % 'N/A'` raises `TypeError`. The callback dies
    on the path that produces the text: typically when a message arrives with an empty
    array, which the placeholder was written for.

    ## Example
    ```python
    velocity = msg.velocity[i] if i < len(msg.velocity) else 'N/A'
    self.get_logger().info(f'velocity: {velocity:.4f}')
    ```

    ## Use instead
    ```python
    velocity = f'{msg.velocity[i]:.4f}' if i < len(msg.velocity) else 'N/A'
    self.get_logger().info(f'velocity: {velocity}')
    ```
    """
    for module, tree, index in installed_trees(package):
        texts = _Texts(tree, index)
        for value, spec, refused, converted in _formatted(tree, index):
            source = value if converted else texts.text(value)
            if source is None:
                continue
            what = f"`{ast.unparse(value)}` is converted to a str" if converted \
                else _what(value, source)
            yield Hit(Span(module.path, value.lineno, value.col_offset + 1),
                      f"{what} and is formatted with `{spec}`, a number's format: Python "
                      f"raises {refused}")
