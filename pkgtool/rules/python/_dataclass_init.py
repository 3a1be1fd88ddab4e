"""The ``__init__`` that ``@dataclass`` writes for a class of the module (PYC048), built as a
function definition so calls can be bound against it.

Only plain cases: ``@dataclass`` or ``@dataclass(...)`` from ``dataclasses`` with keywords
that leave the generated ``__init__`` as the fields say (``frozen``, ``order``, ``eq``,
``repr``, ``unsafe_hash``, ``slots``), a class with no base, metaclass or ``__init__`` of its
own, whose fields are annotated names (``ClassVar`` ones left out) with a default, a
``field(default=..., default_factory=...)``, a ``field(init=False)`` (left out) or nothing.
Anything else (``kw_only``, ``KW_ONLY``, ``InitVar`` with other keywords, a base class) gives
no ``__init__``.
"""

from __future__ import annotations

import ast

from pkgtool.rules.syntax_trees import Index

_PLAIN_KEYWORDS = frozenset({"frozen", "order", "eq", "repr", "unsafe_hash", "slots"})
_FIELD_KEYWORDS = frozenset({"default", "default_factory", "init", "repr", "hash", "compare",
                             "metadata"})


def dataclass_init(cls: ast.ClassDef, index: Index) -> ast.FunctionDef | None:
    """``def __init__(self, <fields>)`` as ``@dataclass`` writes it for ``cls``, or None."""
    if len(cls.decorator_list) != 1 or cls.bases or cls.keywords or \
            not _plain_decorator(cls.decorator_list[0], index):
        return None
    required: list[ast.arg] = []
    optional: list[ast.arg] = []
    for statement in cls.body:
        if isinstance(statement, ast.FunctionDef) and statement.name == "__init__":
            return None
        target = statement.target if isinstance(statement, ast.AnnAssign) else None
        if not isinstance(target, ast.Name):
            continue
        kind = _field_kind(statement, _annotation(statement.annotation, index), index)
        if kind is None:
            return None
        parameter = ast.arg(arg=target.id)
        if kind == "required":
            if optional:
                return None  # Python refuses the class itself (TypeError): not ours to bind
            required.append(parameter)
        elif kind == "optional":
            optional.append(parameter)
    arguments = ast.arguments(posonlyargs=[], args=[ast.arg(arg="self"), *required, *optional],
                              vararg=None, kwonlyargs=[], kw_defaults=[], kwarg=None,
                              defaults=[ast.Constant(...) for _ in optional])
    return ast.FunctionDef(name="__init__", args=arguments, body=[ast.Pass()],
                           decorator_list=[], returns=None, type_params=[], lineno=cls.lineno,
                           col_offset=cls.col_offset)


def _annotation(note: ast.expr, index: Index) -> str:
    """The dotted name an annotation stands for (``typing.ClassVar`` for ``ClassVar[int]``), or
    its text when written as a string."""
    if isinstance(note, ast.Constant) and isinstance(note.value, str):
        return note.value
    if isinstance(note, ast.Subscript):
        note = note.value
    return (index.qualified(note) or "") if isinstance(note, (ast.Name, ast.Attribute)) else ""


def _plain_decorator(decorator: ast.expr, index: Index) -> bool:
    call = decorator if isinstance(decorator, ast.Call) else None
    func = call.func if call is not None else decorator
    if not isinstance(func, (ast.Name, ast.Attribute)) or \
            index.qualified(func) != "dataclasses.dataclass":
        return False
    return call is None or not call.args and all(k.arg in _PLAIN_KEYWORDS for k in call.keywords)


def _field_kind(statement: ast.AnnAssign, annotation: str, index: Index) -> str | None:
    """``required``, ``optional``, ``skipped`` (not an ``__init__`` parameter) or None (a
    field whose effect on ``__init__`` is not read here)."""
    if "ClassVar" in annotation:
        return "skipped"
    if "KW_ONLY" in annotation or "InitVar" in annotation:
        return None
    value = statement.value
    if value is None:
        return "required"
    if isinstance(value, ast.Call) and isinstance(value.func, (ast.Name, ast.Attribute)) and \
            index.qualified(value.func) == "dataclasses.field":
        if value.args or any(k.arg not in _FIELD_KEYWORDS for k in value.keywords):
            return None
        given = {k.arg: k.value for k in value.keywords}
        init = given.get("init")
        if init is not None:
            if not (isinstance(init, ast.Constant) and isinstance(init.value, bool)):
                return None
            if not init.value:
                return "skipped"
        return "optional" if "default" in given or "default_factory" in given else "required"
    return "optional"
