"""Parameters annotated with a known message class (``def describe(msg: JointState)``):
each holds an instance of it, when the function never rebinds the parameter and uses it as
one.

Annotations are often loose (``goal_handle: Fibonacci.Goal`` for the goal handle, ``grid:
OccupancyGrid`` for a NumPy array made of one, ``msg: UUID`` for its ``uuid`` array), so a
parameter counts only when its function takes attributes on it and each is a field of the
class or a near miss of one (a typo).
A method's first parameter (its receiver) is left out, as is ``Optional[...]``/``X |
None``'s ``None``; string annotations are not read.
"""

from __future__ import annotations

import ast
from collections.abc import Iterator
from difflib import get_close_matches

from pkgtool.knowledge.message_fields import Message
from pkgtool.rules.python._message_instances import Instance, Known, parameter_instance
from pkgtool.rules.syntax_trees import Index

_NEAR = 0.8
"""How alike a name must be to a field to be taken for its typo (``velocty``, ``nme``)."""


def annotated_instances(tree: ast.Module, index: Index, known: Known
                        ) -> Iterator[Instance[Message]]:
    """The parameters of the module's functions that hold a known message by annotation."""
    for function in index.functions:
        arguments = function.args
        positional = [*arguments.posonlyargs, *arguments.args]
        if isinstance(index.parents.get(id(function)), ast.ClassDef) and \
                not _static(function):
            positional = positional[1:]
        for parameter in (*positional, *arguments.kwonlyargs):
            message = _annotated_message(parameter.annotation, index, known)
            if message is not None:
                yield from (found for found in parameter_instance(
                    tree, function, parameter.arg, message, None, index) if _used_as_one(found))


def _used_as_one(instance: Instance[Message]) -> bool:
    """True when the function takes attributes on the instance and each is a field of its
    class or is spelled much like one (with none taken, nothing shows the annotation right:
    ``def to_uuid(msg: UUID)`` iterating the ``uint8[16]`` field its callers pass)."""
    message = instance.message
    return bool(instance.uses) and all(
        message.has(use.attr) or use.attr.startswith("_") or
        get_close_matches(use.attr, list(message.fields), n=1, cutoff=_NEAR)
        for use in instance.uses)


def _static(function: ast.FunctionDef | ast.AsyncFunctionDef) -> bool:
    return any(isinstance(d, ast.Name) and d.id == "staticmethod"
               for d in function.decorator_list)


def _annotated_message(note: ast.expr | None, index: Index, known: Known) -> Message | None:
    """The message class an annotation names (``JointState``, ``Twist | None``,
    ``Optional[Pose]``), or None."""
    if isinstance(note, (ast.Name, ast.Attribute)):
        return known(note)
    if isinstance(note, ast.BinOp) and isinstance(note.op, ast.BitOr):
        sides = [s for s in (note.left, note.right)
                 if not (isinstance(s, ast.Constant) and s.value is None)]
        return _annotated_message(sides[0], index, known) if len(sides) == 1 else None
    if isinstance(note, ast.Subscript) and isinstance(note.value, (ast.Name, ast.Attribute)) \
            and (index.qualified(note.value) or "").endswith("Optional"):
        return _annotated_message(note.slice, index, known)
    return None
